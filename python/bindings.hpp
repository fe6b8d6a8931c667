// The `ffrf` Python module's C++ half (`ffrf._ffrf`, pybind11): what its files share. Each study's
// file (run.cpp, compare.cpp, ...) registers one function that takes the scene value and a dict of
// the keyword arguments the Python half (python/ffrf/__init__.py) was given, builds the study's
// request from them — the study's defaults for what is not given, the study's checks for what is —
// runs the study with the GIL released (interruptible.cpp: Ctrl-C stops it), and returns plain
// Python values: the command line's JSON summary as text (report/), its text report, and numpy
// arrays of the bulk data. Nothing here prints.
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>  // in every file: a type's caster must be the same in all of them

#include <complex>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "scene/scene.hpp"
#include "scene/scene_overrides.hpp"
#include "study/boom_choice.hpp"
#include "study/reference.hpp"
#include "study/run_pipeline.hpp"

namespace ffrf::python {

namespace py = pybind11;

// A scene as a value: its file's text and the values given beside it (with_values), and the scene
// they make. A new value is loaded from the same text, so every check runs again on the whole scene.
struct SceneValue {
  std::string path;  // as given to load_scene (messages, the BEM files beside it, provenance)
  std::string text;
  scene::SceneOverrides overrides;
  scene::Scene scene;
};
void bind_scene(py::module_& module);        // scene_value.cpp
void bind_run(py::module_& module);          // run.cpp
void bind_compare(py::module_& module);      // compare.cpp
void bind_recommend(py::module_& module);    // recommend.cpp
void bind_rao(py::module_& module);          // rao.cpp
void bind_modes(py::module_& module);        // modes.cpp
void bind_sweep(py::module_& module);        // sweep.cpp
void bind_stability(py::module_& module);    // stability.cpp
void bind_operability(py::module_& module);  // operability.cpp
void bind_baselines(py::module_& module);    // baseline.cpp

// The keyword arguments of one call (None and absent alike: not given). A value of the wrong type
// raises TypeError naming its keyword.
class Options {
 public:
  explicit Options(py::dict values) : values_(std::move(values)) {}
  bool given(const char* key) const;
  std::optional<double> number(const char* key) const;
  std::optional<long> whole(const char* key) const;
  std::optional<bool> flag(const char* key) const;
  std::string text(const char* key) const;  // empty: not given
  std::optional<std::vector<double>> numbers(const char* key) const;
  std::vector<std::string> texts(const char* key) const;

 private:
  py::dict values_;
};

// The boom model the keywords name (boom, elements, modes, static_modes, stiffening, mode_set,
// stress_recovery).
study::BoomRequest boom_request(const Options& options);
bool boom_given(const Options& options);
// The integrator request the keywords name (integrator, formulation, solver, rtol, atol, duration,
// step, max_order, max_steps, max_wall_time, min_step) over `base` (the study's defaults).
study::DynamicsRequest dynamics_request(const Options& options, study::DynamicsRequest base = {});
// The converged reference's keywords (reference_elements, reference_rtol, reference_bound,
// reference_levels) over the study's defaults, checked (study::validate).
study::ReferenceOptions reference_options(const Options& options);
// The geometric stiffening keyword (empty: not given); throws SettingError for an unknown name.
std::optional<scene::Stiffening> stiffening_keyword(const Options& options);

// Runs `work` with the GIL released, on a thread of its own while this thread watches Python's
// signals: Ctrl-C (KeyboardInterrupt) asks the work to stop (solve/stop_request.hpp), waits for it
// to unwind (its staging directories removed on the way) and raises the KeyboardInterrupt.
void run_interruptible(const std::function<void()>& work);

// numpy arrays (copies).
py::object array_of(const std::vector<double>& values);
py::object complex_array_of(const std::vector<std::complex<double>>& values);
py::object matrix_of(const Eigen::MatrixXd& values);

// The Python keyword of a study setting ("rtol" for the relative tolerance).
std::string_view keyword_of(study::Setting setting);

}  // namespace ffrf::python
