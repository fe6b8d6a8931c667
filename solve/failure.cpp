// Failure names, the remedy of each failure kind in neutral words, and SolverFailure (see failure.hpp).
#include "solve/failure.hpp"

#include "solve/second_order_system.hpp"

namespace ffrf::solve {

std::string_view to_string(FailureKind kind) {
  switch (kind) {
    case FailureKind::divergence: return "divergence";
    case FailureKind::step_size_collapse: return "step-size collapse";
    case FailureKind::error_test_failures: return "error-test failures";
    case FailureKind::newton_divergence: return "Newton divergence";
    case FailureKind::too_much_work: return "too much work";
    case FailureKind::constraint_drift: return "constraint drift";
    case FailureKind::mass_not_positive_definite: return "mass matrix not positive definite";
    case FailureKind::unstable_explicit: return "explicit instability";
    case FailureKind::wire_slack: return "wire slack";
    case FailureKind::luffing_slack: return "luffing wire slack";
    case FailureKind::backstay_slack: return "backstay slack";
    case FailureKind::snap_load: return "snap load";
    case FailureKind::buckling: return "buckling";
    case FailureKind::capsize: return "capsize";
    case FailureKind::deck_submerged: return "deck submerged";
    case FailureKind::cargo_in_water: return "cargo in water";
    case FailureKind::cargo_overturned: return "cargo overturned";
    case FailureKind::model_error: return "model error";
    case FailureKind::setup: return "set-up";
  }
  return "?";
}

std::string_view to_string(Adjustment adjustment) {
  switch (adjustment) {
    case Adjustment::tolerances: return "the tolerances";
    case Adjustment::fixed_step: return "the fixed step";
    case Adjustment::step_limit: return "the step limit";
    case Adjustment::wall_clock_limit: return "the wall-clock limit";
    case Adjustment::step_floor: return "the step-size floor";
    case Adjustment::solver: return "the solver";
    case Adjustment::formulation: return "the constraint formulation";
    case Adjustment::stiffening: return "geometric stiffening";
    case Adjustment::model_size: return "the elements or modes";
    case Adjustment::scene_values: return "the scene's values";
  }
  return "?";
}

std::string_view remedy(FailureKind kind) {
  switch (kind) {
    case FailureKind::divergence:
      return "switch on geometric stiffening (centrifugal for a spinning boom, static near buckling), lower the spin "
             "rate or the load, or tighten the tolerances";
    case FailureKind::step_size_collapse:
      return "look for a discontinuity the steps cannot pass (a wire snap); tighten the absolute tolerance, lower the "
             "step-size floor, or use fewer elements or modes";
    case FailureKind::error_test_failures:
      return "a discontinuity (wire snap) or a stiff transient: tighten the absolute tolerance or resolve the event";
    case FailureKind::newton_divergence:
      return "tighten the tolerances or reduce the fixed step; use minimal coordinates or fewer elements";
    case FailureKind::too_much_work:
      return "the run needs more steps or time than its limit: raise the step or wall-clock limit, loosen the "
             "tolerances, use fewer elements or modes, or an implicit solver (bdf) for a stiff boom";
    case FailureKind::constraint_drift:
      return "stabilize the constraint: the index2, baumgarte or projection formulation, or minimal coordinates (no "
             "drift)";
    case FailureKind::mass_not_positive_definite:
      return "check the scene's masses and added masses (a negative or too small inertia)";
    case FailureKind::unstable_explicit:
      return "reduce the fixed step below the explicit stability limit, use fewer elements or modes, or an implicit "
             "solver (bdf)";
    case FailureKind::wire_slack:
      return "the cargo lost its support: expect snap loads; reduce the wave or the crane motion, or lower the cargo's "
             "excursion (hoisting, a stiffer/longer wire)";
    case FailureKind::luffing_slack:
      return "the boom lost its luffing support and swung on its heel pin: reduce the crane's motion or the load's "
             "release (a dropped or snatched load unloads the boom), or pretension the luffing wires more (stiffer or "
             "shorter wires)";
    case FailureKind::backstay_slack:
      return "the A-frame lost its backstay and swung forward on its deck pin: reduce the crane's motion or the load's "
             "release, or pretension the backstays more (stiffer or shorter backstays, a deck point further aft)";
    case FailureKind::snap_load:
      return "check the wire and boom against the peak; the sampled peak is resolved to the output interval";
    case FailureKind::buckling:
      return "switch on geometric stiffening (static) so the bending stiffness loss under compression is modelled, or "
             "reduce the load";
    case FailureKind::capsize:
      return "the crane is not stable under this load and sea: lower the load or the boom, enlarge the hull, or reduce "
             "the wave";
    case FailureKind::deck_submerged:
      return "lighten the load or shorten the outreach, enlarge the hull's depth, or reduce the wave";
    case FailureKind::cargo_in_water: return "shorten the wire, raise the boom, or reduce the crane's motion";
    case FailureKind::cargo_overturned:
      return "look up the cargo-pitch and hull modes with ffrf rao and move the sea's peak period away from them, "
             "reduce the sea state or the hull's pitch (outreach, hull size), or shorten the wire";
    case FailureKind::model_error: return "check the scene's values; tighten the tolerances";
    case FailureKind::setup:
      return "check the integrator settings (tolerances, step, limits); a set-up call that fails on valid settings "
             "is a bug to report";
  }
  return "?";
}

std::vector<Adjustment> adjustments(FailureKind kind) {
  using A = Adjustment;
  switch (kind) {
    case FailureKind::divergence: return {A::stiffening, A::scene_values, A::tolerances};
    case FailureKind::step_size_collapse: return {A::tolerances, A::step_floor, A::model_size};
    case FailureKind::error_test_failures: return {A::tolerances};
    case FailureKind::newton_divergence: return {A::tolerances, A::fixed_step, A::formulation, A::model_size};
    case FailureKind::too_much_work: return {A::step_limit, A::wall_clock_limit, A::tolerances, A::model_size, A::solver};
    case FailureKind::constraint_drift: return {A::formulation};
    case FailureKind::unstable_explicit: return {A::fixed_step, A::model_size, A::solver};
    case FailureKind::buckling: return {A::stiffening, A::scene_values};
    case FailureKind::model_error: return {A::scene_values, A::tolerances};
    case FailureKind::setup: return {A::tolerances, A::fixed_step};
    case FailureKind::mass_not_positive_definite:
    case FailureKind::wire_slack:
    case FailureKind::luffing_slack:
    case FailureKind::backstay_slack:
    case FailureKind::snap_load:
    case FailureKind::capsize:
    case FailureKind::deck_submerged:
    case FailureKind::cargo_in_water:
    case FailureKind::cargo_overturned: return {A::scene_values};
  }
  return {};
}

SolverFailure::SolverFailure(FailureKind kind, std::string solver, std::string cause, double time)
    : SolverFailure(kind, std::move(solver), std::move(cause), time, std::string(solve::remedy(kind))) {}

SolverFailure::SolverFailure(FailureKind kind, std::string solver, std::string cause, double time, std::string remedy,
                             double value)
    : std::runtime_error(solver + " failed at t = " + std::to_string(time) + " s (" + std::string(to_string(kind)) +
                         "): " + cause + ". Try: " + remedy),
      kind_(kind), solver_(std::move(solver)), cause_(std::move(cause)), remedy_(std::move(remedy)), time_(time),
      value_(value) {}

FailureKind model_failure_kind(const std::exception& error) {
  return dynamic_cast<const MassMatrixError*>(&error) != nullptr ? FailureKind::mass_not_positive_definite
                                                                 : FailureKind::model_error;
}

}  // namespace ffrf::solve
