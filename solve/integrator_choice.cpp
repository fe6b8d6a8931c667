// Names of the constraint formulations and solvers (see integrator_choice.hpp); the valid pairs
// are in integrator_table.cpp.
#include "solve/integrator_choice.hpp"

namespace ffrf::solve {

std::string_view to_string(Formulation formulation) {
  switch (formulation) {
    case Formulation::minimal: return "minimal";
    case Formulation::index3: return "index3";
    case Formulation::index2: return "index2";
    case Formulation::index1: return "index1";
    case Formulation::baumgarte: return "baumgarte";
    case Formulation::projection: return "projection";
  }
  return "?";
}

std::string_view to_string(Solver solver) {
  switch (solver) {
    case Solver::bdf: return "bdf";
    case Solver::explicit_rk: return "explicit-rk";
    case Solver::generalized_alpha: return "generalized-alpha";
  }
  return "?";
}

std::optional<Formulation> parse_formulation(std::string_view text) {
  for (const Formulation f : all_formulations) {
    if (text == to_string(f)) return f;
  }
  return std::nullopt;
}

std::optional<Solver> parse_solver(std::string_view text) {
  for (const Solver s : all_solvers) {
    if (text == to_string(s)) return s;
  }
  return std::nullopt;
}

// Appended piece by piece: `(text.empty() ? "" : "|") + std::string(...)` makes GCC 12 at -O3 report
// a false -Wstringop-overflow on the temporary's memcpy.
std::string formulation_choices() {
  std::string text;
  for (const Formulation f : all_formulations) {
    if (!text.empty()) text += '|';
    text += to_string(f);
  }
  return text;
}

std::string solver_choices() {
  std::string text;
  for (const Solver s : all_solvers) {
    if (!text.empty()) text += '|';
    text += to_string(s);
  }
  return text;
}

InvalidIntegrator::InvalidIntegrator(Integrator choice)
    : std::invalid_argument("formulation " + std::string(to_string(choice.formulation)) + " with solver " +
                            std::string(to_string(choice.solver)) + " is not an implemented integrator; valid pairs: " +
                            valid_integrators()),
      choice_(choice) {}

Integrator integrator(Formulation formulation, Solver solver) {
  const Integrator choice{formulation, solver};
  if (!is_valid(choice)) throw InvalidIntegrator(choice);
  return choice;
}

}  // namespace ffrf::solve
