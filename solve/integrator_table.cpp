// The valid integrators (see integrator_table.hpp): one row per formulation × solver pair.
#include "solve/integrator_table.hpp"

#include <string>

#include "solve/integration.hpp"

namespace ffrf::solve {

namespace {

constexpr IntegratorEntry table[] = {
    {Integrator::cvode, "cvode", "CVODE", integrate_minimal, "minimal coordinates, BDF (CVODE)"},
    {Integrator::arkode, "arkode", "ARKODE ERK", integrate_explicit,
     "minimal coordinates, explicit Runge-Kutta (ARKODE; adaptive, or fixed with a step)"},
    {Integrator::ida, "ida", "IDA", integrate_lagrange, "Lagrange multipliers, stabilized index-2 DAE, BDF (IDA)"},
    {Integrator::generalized_alpha, "generalized-alpha", "generalized-α", integrate_generalized_alpha,
     "Lagrange multipliers, index 3, fixed-step generalized-alpha (needs a step)"},
    {Integrator::index1, "index1", "CVODE (index1)", integrate_index1,
     "Lagrange multipliers, index-1 ODE, BDF (CVODE): unstabilized, the constraint drifts"},
    {Integrator::baumgarte, "baumgarte", "CVODE (baumgarte)", integrate_index1,
     "index-1 ODE with Baumgarte feedback (omega_b = 10 rad/s), BDF (CVODE)"},
    {Integrator::projection, "projection", "CVODE (projection)", integrate_index1,
     "index-1 ODE projected onto the constraint after every step, BDF (CVODE)"},
};

}  // namespace

std::span<const IntegratorEntry> integrator_table() { return table; }

bool is_valid(Integrator choice) {
  for (const IntegratorEntry& entry : table) {
    if (entry.choice == choice) return true;
  }
  return false;
}

const IntegratorEntry& integrator_entry(Integrator choice) {
  for (const IntegratorEntry& entry : table) {
    if (entry.choice == choice) return entry;
  }
  throw InvalidIntegrator(choice);
}

std::string_view to_string(Integrator choice) {
  for (const IntegratorEntry& entry : table) {
    if (entry.choice == choice) return entry.name;
  }
  return "invalid";
}

std::optional<Integrator> parse_integrator(std::string_view text) {
  for (const IntegratorEntry& entry : table) {
    if (text == entry.name) return entry.choice;
  }
  return std::nullopt;
}

// Appended piece by piece: `(text.empty() ? "" : "|") + std::string(...)` makes GCC 12 at -O3 report
// a false -Wstringop-overflow on the temporary's memcpy.
std::string integrator_choices() {
  std::string text;
  for (const IntegratorEntry& entry : table) {
    if (!text.empty()) text += '|';
    text += entry.name;
  }
  return text;
}

std::string valid_integrators() {
  std::string text;
  for (const IntegratorEntry& entry : table) {
    if (!text.empty()) text += ", ";
    text += to_string(entry.choice.formulation);
    text += " × ";
    text += to_string(entry.choice.solver);
    text += " (";
    text += entry.name;
    text += ")";
  }
  return text;
}

std::string_view solver_label(Integrator choice) { return integrator_entry(choice).label; }

}  // namespace ffrf::solve
