// The keyword arguments of a call as the studies' requests (see bindings.hpp): read, not checked —
// every range and choice is checked by the study the request goes to (study::boom_choice,
// study::integrator_settings, study::validate, ...), which names the setting; keyword_of() names it
// as the Python keyword.
#include <fmt/format.h>

#include <algorithm>

#include "python/bindings.hpp"

namespace ffrf::python {
namespace {

template <class T>
T cast_keyword(const py::handle& value, const char* key, const char* expected) {
  try {
    return value.cast<T>();
  } catch (const py::cast_error&) {
    throw py::type_error(fmt::format("{}: expected {}, got {}", key, expected, std::string(py::str(py::type::of(value).attr("__name__")))));
  }
}

}  // namespace

bool Options::given(const char* key) const { return values_.contains(key) && !values_[key].is_none(); }

std::optional<double> Options::number(const char* key) const {
  if (!given(key)) return std::nullopt;
  return cast_keyword<double>(values_[key], key, "a number");
}

std::optional<long> Options::whole(const char* key) const {
  if (!given(key)) return std::nullopt;
  const py::handle value = values_[key];
  if (py::isinstance<py::bool_>(value)) throw py::type_error(fmt::format("{}: expected a whole number, got bool", key));
  return cast_keyword<long>(value, key, "a whole number");
}

std::optional<bool> Options::flag(const char* key) const {
  if (!given(key)) return std::nullopt;
  const py::handle value = values_[key];
  if (!py::isinstance<py::bool_>(value)) throw py::type_error(fmt::format("{}: expected True or False", key));
  return value.cast<bool>();
}

std::string Options::text(const char* key) const {
  if (!given(key)) return {};
  const py::handle value = values_[key];
  if (!py::isinstance<py::str>(value)) throw py::type_error(fmt::format("{}: expected a str", key));
  return value.cast<std::string>();
}

std::optional<std::vector<double>> Options::numbers(const char* key) const {
  if (!given(key)) return std::nullopt;
  std::vector<double> values;
  const py::handle given_values = values_[key];
  if (py::isinstance<py::str>(given_values)) throw py::type_error(fmt::format("{}: expected a sequence of numbers, got str", key));
  py::iterator item;
  try {
    item = py::iter(given_values);
  } catch (const py::error_already_set&) {
    throw py::type_error(fmt::format("{}: expected a sequence of numbers", key));
  }
  for (; item != py::iterator::sentinel(); ++item) values.push_back(cast_keyword<double>(*item, key, "numbers"));
  return values;
}

std::vector<std::string> Options::texts(const char* key) const {
  if (!given(key)) return {};
  const py::handle value = values_[key];
  if (py::isinstance<py::str>(value)) return {value.cast<std::string>()};
  std::vector<std::string> values;
  py::iterator item;
  try {
    item = py::iter(value);
  } catch (const py::error_already_set&) {
    throw py::type_error(fmt::format("{}: expected a str or a sequence of str", key));
  }
  for (; item != py::iterator::sentinel(); ++item) {
    if (!py::isinstance<py::str>(*item)) throw py::type_error(fmt::format("{}: expected str items", key));
    values.push_back((*item).cast<std::string>());
  }
  return values;
}

bool boom_given(const Options& options) {
  for (const char* key : {"boom", "elements", "modes", "static_modes", "stiffening", "mode_set", "stress_recovery"}) {
    if (options.given(key)) return true;
  }
  return false;
}

study::BoomRequest boom_request(const Options& options) {
  study::BoomRequest request;
  request.kind = options.text("boom");
  if (const auto elements = options.whole("elements")) request.elements = static_cast<int>(std::clamp(*elements, -1L, 1L << 30));
  if (const auto modes = options.whole("modes")) request.modes = static_cast<int>(std::clamp(*modes, -1L, 1L << 30));
  request.static_modes = options.flag("static_modes");
  request.stiffening = options.text("stiffening");
  request.mode_set = options.text("mode_set");
  request.stress_recovery = options.text("stress_recovery");
  return request;
}

study::DynamicsRequest dynamics_request(const Options& options, study::DynamicsRequest base) {
  const std::string integrator = options.text("integrator"), formulation = options.text("formulation"),
                    solver = options.text("solver");
  if (!integrator.empty() || !formulation.empty() || !solver.empty()) {
    base.integrator = study::integrator_choice(integrator, formulation, solver);
  }
  base.relative_tolerance = options.number("rtol").value_or(base.relative_tolerance);
  base.absolute_tolerance = options.number("atol").value_or(base.absolute_tolerance);
  if (const auto duration = options.number("duration")) base.duration = duration;
  base.fixed_step = options.number("step").value_or(base.fixed_step);
  if (const auto order = options.whole("max_order")) base.max_order = static_cast<int>(std::clamp(*order, -1L, 100L));
  base.work.max_steps = options.whole("max_steps").value_or(base.work.max_steps);
  base.work.max_wall_seconds = options.number("max_wall_time").value_or(base.work.max_wall_seconds);
  base.work.min_step = options.number("min_step").value_or(base.work.min_step);
  return base;
}

study::ReferenceOptions reference_options(const Options& options) {
  study::ReferenceOptions reference;
  if (const auto elements = options.whole("reference_elements")) reference.start_elements = static_cast<int>(std::clamp(*elements, -1L, 1L << 30));
  reference.start_relative_tolerance = options.number("reference_rtol").value_or(reference.start_relative_tolerance);
  reference.bound = options.number("reference_bound").value_or(reference.bound);
  if (const auto levels = options.whole("reference_levels")) reference.max_levels = static_cast<int>(std::clamp(*levels, -1L, 100L));
  study::validate(reference);
  return reference;
}

std::optional<scene::Stiffening> stiffening_keyword(const Options& options) {
  return study::stiffening_setting(options.text("stiffening"));
}

std::string_view keyword_of(study::Setting setting) {
  using study::Setting;
  switch (setting) {
    case Setting::relative_tolerance: return "rtol";
    case Setting::absolute_tolerance: return "atol";
    case Setting::duration: return "duration";
    case Setting::fixed_step: return "step";
    case Setting::max_order: return "max_order";
    case Setting::reference_elements: return "reference_elements";
    case Setting::reference_tolerance: return "reference_rtol";
    case Setting::reference_bound: return "reference_bound";
    case Setting::reference_levels: return "reference_levels";
    case Setting::tolerance: return "tolerance";
    case Setting::jobs: return "jobs";
    case Setting::elements: return "elements";
    case Setting::boom_model: return "boom";
    case Setting::modes: return "modes";
    case Setting::stiffening: return "stiffening";
    case Setting::mode_set: return "mode_set";
    case Setting::stress_recovery: return "stress_recovery";
    case Setting::integrator: return "integrator";
    case Setting::formulation: return "formulation";
    case Setting::solver: return "solver";
    case Setting::step_limit: return "max_steps";
    case Setting::wall_clock_limit: return "max_wall_time";
    case Setting::step_floor: return "min_step";
    case Setting::wave_periods: return "periods";
    case Setting::wave_frequencies: return "frequencies";
    case Setting::outputs: return "outputs";
    case Setting::eigen_solver: return "solver";
    case Setting::boundary: return "boundary";
    case Setting::grid: return "grid";
    case Setting::headings: return "headings";
  }
  return "?";
}

}  // namespace ffrf::python
