// Settings and results of an integration of a second-order system (solve/second_order_system.hpp):
// which integrator with which tolerances, the output times, the solver statistics every run must
// record, and the located events. The samples go to an OutputSink (solve/output_sink.hpp).
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "solve/failure.hpp"
#include "solve/integrator_choice.hpp"
#include "solve/output_sink.hpp"
#include "solve/second_order_system.hpp"

namespace ffrf::solve {

// The integrator is a constraint formulation × a solver (solve/integrator_choice.hpp); the valid
// pairs and the function each runs are in solve/integrator_table.cpp.

// The work a run may do before it ends with a "too much work" (steps, wall clock) or "step-size
// collapse" (floor) failure, for every integrator. study/work_limits.hpp estimates fixed-step work
// before a run; these limits stop adaptive runs that would otherwise crawl (explicit RK on a stiff
// boom, a step size collapsing towards 1e-24 s).
struct WorkLimits {
  long max_steps = 10000000;  // steps over the whole run (study::max_fixed_steps for fixed steps)
  double max_wall_seconds = std::numeric_limits<double>::infinity();  // wall clock of the integration [s]
  double min_step = 0.0;      // step-size floor of the adaptive solvers [s]; 0: none (the solver's own)
};

struct IntegratorSettings {
  Integrator kind = Integrator::cvode;  // formulation × solver
  double relative_tolerance = 1e-6;
  double absolute_tolerance = 1e-8;  // scaled by SecondOrderSystem::coordinate_scale()
  double duration = 120.0;           // [s]
  double output_interval = 0.05;     // [s]
  long max_steps = 500000;           // per output interval (SUNDIALS semantics)
  WorkLimits work = {};              // over the whole run
  // Fixed step [s]: required > 0 for generalized-α (rounded down to divide the output interval);
  // for arkode 0 = adaptive with the tolerances, > 0 = this fixed step (outputs interpolated).
  double fixed_step = 0.0;
  double spectral_radius = 0.8;      // ρ∞ ∈ [0, 1] of generalized-α (1: no numerical dissipation)
  // Largest BDF order of CVODE and IDA (1–5). Orders 3–5 are not A-stable: their stability regions
  // leave out part of the imaginary axis, so undamped stiff modes (a boom without structural damping)
  // force steps that resolve the highest frequency; order ≤ 2 is A-stable (docs/stability.md).
  int max_order = 5;
  // Baumgarte stabilization frequency ω_b [rad/s] of `baumgarte`: C̈ + 2ω_b Ċ + ω_b² C = 0 (critically
  // damped drift). 10 rad/s is above the wave (0.63 rad/s) and the cargo's swing and heave-on-wire
  // modes, so the feedback damps drift faster than the motion varies, and low enough that the added
  // eigenvalues (−ω_b, double) stay well inside what BDF resolves at the motion's step sizes.
  double baumgarte_frequency = 10.0;
  bool progress = false;             // print progress on stderr (callers set it for terminals only)
};

struct SolverStats {
  long steps = 0;
  long function_evaluations = 0;   // RHS (CVODE) or residual (IDA), including those for Jacobians
  long jacobian_evaluations = 0;
  long newton_iterations = 0;
  long error_test_failures = 0;
  long convergence_failures = 0;
  double step = 0.0;               // the step actually taken by a fixed-step run [s] (0: adaptive)
  long projections = 0;            // constraint projections (CVODE's projection variant only)
  long linear_setups = 0;          // Newton-matrix factorizations (set-ups of the linear solver)
  double wall_seconds = 0.0;
};

// An event function crossed zero at `time`: function `index` of SecondOrderSystem::*_events, going
// negative (falling) or positive.
struct Event {
  double time = 0.0;
  int index = 0;
  bool falling = false;
};

// What an integration records besides the samples its sink took: the output times, the statistics
// and the events. A system's run result extends it with its samples (the partial result a
// SolverFailure carries is then the system's, see SolverFailure::attach_partial).
struct IntegrationRecord {
  std::vector<double> time;
  SolverStats stats;
  std::vector<Event> events;

  IntegrationRecord() = default;
  IntegrationRecord(const IntegrationRecord&) = default;
  IntegrationRecord(IntegrationRecord&&) = default;
  IntegrationRecord& operator=(const IntegrationRecord&) = default;
  IntegrationRecord& operator=(IntegrationRecord&&) = default;
  virtual ~IntegrationRecord() = default;  // a system's run result extends it (SolverFailure::partial)
};

// CVODE (BDF, Newton, dense Jacobian) on the minimal-coordinate ODE from z0 (ż0 = 0).
IntegrationRecord integrate_minimal(SecondOrderSystem& system, OutputSink& sink, const Eigen::VectorXd& z0,
                                    const IntegratorSettings& settings);
// IDA on the stabilized index-2 (Gear–Gupta–Leimkuhler) DAE in full coordinates from z0 at rest.
IntegrationRecord integrate_lagrange(SecondOrderSystem& system, OutputSink& sink, const Eigen::VectorXd& z0,
                                     const IntegratorSettings& settings);
// ARKODE ERKStep (explicit Runge–Kutta, Zonneveld 4(3)) on the minimal-coordinate ODE from z0
// at rest; adaptive, or fixed step with instability detection (SolverFailure "unstable: ...").
IntegrationRecord integrate_explicit(SecondOrderSystem& system, OutputSink& sink, const Eigen::VectorXd& z0,
                                     const IntegratorSettings& settings);
// Largest fixed ERK step that is linearly stable about (z0, ż = 0) at t = 0: min over the
// eigenvalues μ of ∂ẏ/∂y (finite differences) of the stability boundary of the table along μ's ray / |μ|.
double explicit_stable_step(SecondOrderSystem& system, const Eigen::VectorXd& z0);
// The ERK table's stability boundary on the imaginary axis (h ω_max limit for undamped modes).
double explicit_imaginary_axis_boundary();
// Generalized-α (Chung–Hulbert ρ∞, Arnold–Brüls index-3 constraints) in full coordinates from z0
// at rest, fixed step settings.fixed_step; Newton on (q̈, λ) with a modified-Newton iteration matrix.
IntegrationRecord integrate_generalized_alpha(SecondOrderSystem& system, OutputSink& sink, const Eigen::VectorXd& z0,
                                              const IntegratorSettings& settings);
// CVODE (BDF, Newton, dense Jacobian) on the full coordinates y = (q, v), q̇ = v, with v̇ and λ from
// the index-1 system [M C_qᵀ; C_q 0][v̇; λ] = [Q; γ − 2αĊ − β²C] from z0 at rest. settings.kind
// chooses the constraint treatment: index1 (α = β = 0: drifts), baumgarte (α = β = ω_b,
// settings.baumgarte_frequency) or projection (α = β = 0, CVODE projects q onto C(q) = 0 and v onto
// C_q v = 0 in the mass-weighted norm after every step).
IntegrationRecord integrate_index1(SecondOrderSystem& system, OutputSink& sink, const Eigen::VectorXd& z0,
                                   const IntegratorSettings& settings);
// The row of settings.kind in solve/integrator_table.cpp (InvalidIntegrator for a pair that is not
// implemented, as a SolverFailure of kind set-up). A system with no minimal coordinates (fully
// prescribed) is sampled at the output times without integrating, in the minimal formulation.
IntegrationRecord integrate(SecondOrderSystem& system, OutputSink& sink, const Eigen::VectorXd& z0,
                            const IntegratorSettings& settings);

}  // namespace ffrf::solve
