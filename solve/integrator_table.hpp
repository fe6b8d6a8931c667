// The valid integrators, one row each (integrator_table.cpp): the formulation × solver pair, its
// name, what messages call its solver, and the function that integrates a system with it. Adding an
// integrator is a new integrate_*.cpp, its row, and its line in solve/CMakeLists.txt
// (docs/integrators.md).
#pragma once

#include <Eigen/Core>
#include <span>
#include <string_view>

#include "solve/integrator_choice.hpp"

namespace ffrf::solve {

class SecondOrderSystem;
class OutputSink;
struct IntegratorSettings;
struct IntegrationRecord;

using IntegrateFunction = IntegrationRecord (*)(SecondOrderSystem& system, OutputSink& sink, const Eigen::VectorXd& z0,
                                                const IntegratorSettings& settings);

struct IntegratorEntry {
  Integrator choice;
  std::string_view name;     // the --integrator name ("cvode")
  std::string_view label;    // the solver in messages ("CVODE")
  IntegrateFunction integrate;
  std::string_view summary;  // one line for --help and docs
};

std::span<const IntegratorEntry> integrator_table();
// The row of a valid pair, or InvalidIntegrator.
const IntegratorEntry& integrator_entry(Integrator choice);

}  // namespace ffrf::solve
