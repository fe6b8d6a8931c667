// The sweep grid (see sweep_grid.hpp).
#include "study/sweep_grid.hpp"

#include "study/run_pipeline.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>


namespace ffrf::study {
namespace {

using scene::BoomChoice;
using scene::BoomKind;
using solve::Integrator;

struct GridSpec {
  std::vector<int> nodal_elements;
  std::vector<int> modal_modes;      // on the N = 16 mesh, each with and without static modes
  std::vector<double> tolerances;    // for the adaptive integrators
  std::vector<Integrator> adaptive;  // cvode, ida, arkode (adaptive)
  std::vector<double> alpha_steps;   // generalized-α fixed steps [s]
  std::vector<double> erk_factors;   // ARKODE fixed step as a multiple of the stability limit
};

GridSpec spec(SweepGrid grid) {
  switch (grid) {
    case SweepGrid::quick:
      return {{1, 4, 16}, {1, 2, 4}, {1e-6}, {Integrator::cvode}, {0.01}, {}};
    case SweepGrid::medium:
      return {{1, 2, 4, 8, 16, 32}, {1, 2, 3, 4, 6, 8, 12}, {1e-4, 1e-6, 1e-8}, {Integrator::cvode},
              {0.05, 0.01}, {0.5, 2.0}};
    case SweepGrid::full:
      return {{1, 2, 4, 8, 16, 32, 64}, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}, {1e-4, 1e-6, 1e-8},
              {Integrator::cvode, Integrator::ida, Integrator::arkode}, {0.05, 0.01, 0.0025}, {0.5, 2.0}};
  }
  return {};
}

std::vector<BoomChoice> models(const GridSpec& s) {
  std::vector<BoomChoice> list{{BoomKind::rigid, 1}};
  for (int n : s.nodal_elements) list.push_back({BoomKind::nodal, n});
  for (const bool static_modes : {false, true}) {
    for (int k : s.modal_modes) list.push_back({BoomKind::modal, 16, k, static_modes});
  }
  return list;
}

}  // namespace

std::string_view to_string(SweepGrid grid) {
  switch (grid) {
    case SweepGrid::quick: return "quick";
    case SweepGrid::medium: return "medium";
    case SweepGrid::full: return "full";
  }
  return "?";
}

SweepGrid parse_sweep_grid(std::string_view name) {
  for (const SweepGrid grid : {SweepGrid::quick, SweepGrid::medium, SweepGrid::full}) {
    if (to_string(grid) == name) return grid;
  }
  throw SettingError(Setting::grid, std::string(name), "unknown sweep grid; choose one of quick, medium, full");
}

std::string grid_description(SweepGrid grid) {
  const GridSpec s = spec(grid);
  std::string adaptive;
  for (Integrator i : s.adaptive) adaptive += std::string(solve::to_string(i)) + ", ";
  std::string text = fmt::format(
      "grid `{}`: models rigid, nodal N ∈ {{{}}}, modal k ∈ {{{}}} with and without static modes (N = 16 mesh); "
      "integrators {}at rtol ∈ {{{}}} (and at the model-choice rtol of the verdict's τ when not among them); "
      "generalized-alpha at h ∈ {{{}}} s",
      to_string(grid), fmt::join(s.nodal_elements, ", "), fmt::join(s.modal_modes, ", "), adaptive,
      fmt::join(s.tolerances, ", "), fmt::join(s.alpha_steps, ", "));
  text += s.erk_factors.empty()
              ? "; ARKODE explicit RK at a fixed step 2× its stability limit on the rigid crane only (a run that must fail)"
              : fmt::format("; ARKODE explicit RK at fixed steps {{{}}}× its stability limit", fmt::join(s.erk_factors, ", "));
  return text;
}

std::vector<SweepConfig> sweep_grid(SweepGrid grid, bool radiation_axis, double choice_rtol, bool mode_set_axis) {
  GridSpec s = spec(grid);
  // The adaptive integrators also run at the model-choice rtol (the one the verdict names its
  // cheapest model from), appended when the grid lacks it: the default grids have 1e-6, τ = 1 %'s.
  const bool has_choice = std::any_of(s.tolerances.begin(), s.tolerances.end(), [&](double rtol) {
    return std::abs(std::log10(rtol) - std::log10(choice_rtol)) < 1e-6;
  });
  if (!has_choice) s.tolerances.push_back(choice_rtol);
  std::vector<SweepConfig> configs;
  auto add = [&](const BoomChoice& choice, Integrator integrator, double rtol, double step, double factor) {
    configs.push_back({static_cast<int>(configs.size()), choice, integrator, rtol, step, factor, std::nullopt});
  };
  std::vector<BoomChoice> list = models(s);
  if (mode_set_axis) {
    const std::size_t plain = list.size();
    for (const fem::Boundary set : {fem::Boundary::free_free, fem::Boundary::pinned_pinned}) {
      for (std::size_t i = 0; i < plain; ++i) {
        if (list[i].kind != BoomKind::modal) continue;
        BoomChoice other = list[i];
        other.mode_set = set;
        list.push_back(other);
      }
    }
  }
  for (const BoomChoice& choice : list) {
    for (Integrator integrator : s.adaptive) {
      for (double rtol : s.tolerances) add(choice, integrator, rtol, 0.0, 0.0);
    }
    for (double h : s.alpha_steps) add(choice, Integrator::generalized_alpha, 1e-6, h, 0.0);
    for (double factor : s.erk_factors) add(choice, Integrator::arkode, 0.0, 0.0, factor);
  }
  // The quick grid's one configuration that must fail: explicit RK past its stability limit.
  if (s.erk_factors.empty()) add(list.front(), Integrator::arkode, 0.0, 0.0, 2.0);
  if (!radiation_axis) return configs;
  std::vector<SweepConfig> crossed;
  for (const SweepConfig& config : configs) {
    for (const auto kind : {hydro::RadiationKind::constant, hydro::RadiationKind::state_space,
                            hydro::RadiationKind::convolution}) {
      SweepConfig c = config;
      c.id = static_cast<int>(crossed.size());
      c.radiation = kind;
      crossed.push_back(c);
    }
  }
  return crossed;
}

std::string radiation_name(const SweepConfig& config) {
  return config.radiation ? std::string(hydro::to_string(*config.radiation)) : std::string();
}

std::string model_family(const BoomChoice& choice) {
  switch (choice.kind) {
    case BoomKind::rigid: return "rigid";
    case BoomKind::nodal: return "nodal";
    case BoomKind::modal: return choice.static_modes ? "modal+static" : "modal";
  }
  return "?";
}

std::string integrator_label(const SweepConfig& c) {
  const std::string name(solve::to_string(c.integrator));
  if (c.stability_factor > 0.0) return fmt::format("{} h {:g}x limit", name, c.stability_factor);
  if (c.step > 0.0) return fmt::format("{} h {:g} s", name, c.step);
  return fmt::format("{} rtol {:g}", name, c.rtol);
}

}  // namespace ffrf::study
