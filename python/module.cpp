// The `ffrf._ffrf` extension module: registers each study's function (bindings.hpp) and turns the
// library's errors into the Python exceptions of python/ffrf/_errors.py, with the command line's
// messages: a scene's problems (SceneError, each problem's file, line, key, value, message and
// origin), a setting out of range (SettingError, named by its keyword), a solver that could not
// finish (SolverFailure: kind, solver, time, cause, remedy and the keywords to adjust), a baseline
// file that cannot be used (BaselineFileError), and a stop request (KeyboardInterrupt).
#include <fmt/format.h>

#include <new>

#include "python/bindings.hpp"
#include "report/baseline_file.hpp"
#include "scene/scene_loader.hpp"
#include "solve/failure.hpp"
#include "solve/stop_request.hpp"
#include "study/baseline_check.hpp"

namespace ffrf::python {
namespace {

// The keywords behind a remedy's adjustment ("rtol/atol" for the tolerances).
std::string keywords_of(solve::Adjustment adjustment) {
  switch (adjustment) {
    case solve::Adjustment::tolerances: return "rtol/atol";
    case solve::Adjustment::fixed_step: return "step";
    case solve::Adjustment::step_limit: return "max_steps";
    case solve::Adjustment::wall_clock_limit: return "max_wall_time";
    case solve::Adjustment::step_floor: return "min_step";
    case solve::Adjustment::solver: return "solver";
    case solve::Adjustment::formulation: return "formulation";
    case solve::Adjustment::stiffening: return "stiffening";
    case solve::Adjustment::model_size: return "elements/modes";
    case solve::Adjustment::scene_values: return "the scene's values (with_values)";
  }
  return "?";
}

void raise(const char* name, const std::string& message, const py::dict& fields) {
  const py::object type = py::module_::import("ffrf._errors").attr(name);
  const py::object error = type(message, **fields);
  PyErr_SetObject(type.ptr(), error.ptr());
}

void translate(std::exception_ptr pending) {
  try {
    std::rethrow_exception(pending);
  } catch (const scene::SceneError& error) {
    py::list problems;
    for (const scene::SceneProblem& p : error.problems()) {
      problems.append(py::dict(py::arg("file") = p.file, py::arg("line") = p.line, py::arg("column") = p.column,
                               py::arg("key") = p.key, py::arg("value") = p.value, py::arg("message") = p.message,
                               py::arg("origin") = p.origin, py::arg("text") = scene::format_problem(p)));
    }
    raise("SceneError", error.what(), py::dict(py::arg("problems") = problems));
  } catch (const study::SettingError& error) {
    const std::string_view keyword = keyword_of(error.setting());
    raise("SettingError", fmt::format("{}={}: {}", keyword, error.value(), error.problem()),
          py::dict(py::arg("keyword") = std::string(keyword), py::arg("setting") = std::string(study::to_string(error.setting())),
                   py::arg("value") = error.value(), py::arg("problem") = error.problem()));
  } catch (const study::ToleranceError& error) {
    raise("SettingError", fmt::format("tolerances[{}]={}: {}", error.name(), error.value(), error.problem()),
          py::dict(py::arg("keyword") = "tolerances", py::arg("setting") = error.name(),
                   py::arg("value") = fmt::format("{}", error.value()), py::arg("problem") = error.problem()));
  } catch (const solve::SolverFailure& failure) {
    std::string keywords;
    for (const solve::Adjustment adjustment : failure.adjustments()) {
      keywords += (keywords.empty() ? "" : ", ") + keywords_of(adjustment);
    }
    raise("SolverFailure",
          fmt::format("solver failure ({}): {}{}", solve::to_string(failure.kind()), failure.what(),
                      keywords.empty() ? "" : " (adjust: " + keywords + ")"),
          py::dict(py::arg("kind") = std::string(solve::to_string(failure.kind())), py::arg("solver") = failure.solver(),
                   py::arg("time") = failure.time(), py::arg("cause") = failure.cause(), py::arg("remedy") = failure.remedy(),
                   py::arg("value") = failure.value(), py::arg("adjust") = keywords));
  } catch (const report::BaselineFileError& error) {
    raise("BaselineFileError", error.what(),
          py::dict(py::arg("file") = error.file(), py::arg("key") = error.key(), py::arg("value") = error.value(),
                   py::arg("problem") = error.problem()));
  } catch (const std::bad_alloc&) {
    PyErr_SetString(PyExc_MemoryError,
                    "out of memory: use fewer elements or modes, a shorter duration or a longer output interval");
  } catch (const std::invalid_argument& error) {  // a setting the study refused in words of its own
    raise("SettingError", error.what(), py::dict());
  } catch (const solve::Interrupted&) {  // a stop request that was not this call's
    solve::clear_stop_request();
    PyErr_SetNone(PyExc_KeyboardInterrupt);
  }
}

}  // namespace
}  // namespace ffrf::python

PYBIND11_MODULE(_ffrf, module) {
  using namespace ffrf::python;
  module.doc() = "ffrf's studies (the C++ half of the ffrf package; use `import ffrf`)";
  py::register_exception_translator(&translate);
  bind_scene(module);
  bind_run(module);
  bind_compare(module);
  bind_recommend(module);
  bind_rao(module);
  bind_modes(module);
  bind_sweep(module);
  bind_stability(module);
  bind_operability(module);
  bind_baselines(module);
}
