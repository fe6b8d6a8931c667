// An integrator is two choices, so each can be compared on its own: how the clamp at B enters the equations of motion
// (the constraint formulation) and which time integrator solves them (the solver).
//  formulations  minimal     minimal coordinates: the clamp eliminated, an ODE (no constraint, no drift)
//                index3      Lagrange multipliers, C(q) = 0 itself (index 3; Arnold–Brüls scaling)
//                index2      Lagrange multipliers, stabilized index 2 (Gear–Gupta–Leimkuhler): C = 0 and Ċ = 0
//                index1      Lagrange multipliers, C̈ = 0 (the clamp differentiated twice): an ODE that drifts
//                baumgarte   index 1 with Baumgarte's feedback C̈ + 2ω_b Ċ + ω_b² C = 0
//                projection  index 1, projected onto C = 0, Ċ = 0 after every step
//  solvers       bdf                variable-order BDF with Newton (CVODE for ODEs, IDA for the DAE)
//                explicit-rk        adaptive or fixed-step explicit Runge–Kutta (ARKODE ERKStep)
//                generalized-alpha  fixed-step generalized-α (Chung–Hulbert), the structural-dynamics standard
// Not every pair is implemented: solve/integrator_table.cpp lists the valid ones, each with the
// name it had before the split (`cvode`, `ida`, ...), which stays a name of the pair.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace ffrf::solve {

enum class Formulation { minimal, index3, index2, index1, baumgarte, projection };
enum class Solver { bdf, explicit_rk, generalized_alpha };

inline constexpr Formulation all_formulations[] = {Formulation::minimal, Formulation::index3,    Formulation::index2,
                                                   Formulation::index1,  Formulation::baumgarte, Formulation::projection};
inline constexpr Solver all_solvers[] = {Solver::bdf, Solver::explicit_rk, Solver::generalized_alpha};

std::string_view to_string(Formulation formulation);  // "minimal", "index3", ...
std::string_view to_string(Solver solver);            // "bdf", "explicit-rk", "generalized-alpha"
std::optional<Formulation> parse_formulation(std::string_view text);
std::optional<Solver> parse_solver(std::string_view text);
std::string formulation_choices();  // "minimal|index3|index2|index1|baumgarte|projection"
std::string solver_choices();       // "bdf|explicit-rk|generalized-alpha"

struct Integrator {
  Formulation formulation = Formulation::minimal;
  Solver solver = Solver::bdf;
  friend constexpr bool operator==(const Integrator&, const Integrator&) = default;
  // The names of the valid pairs (the command line's --integrator names).
  static const Integrator cvode, ida, arkode, generalized_alpha, index1, baumgarte, projection;
};
inline constexpr Integrator Integrator::cvode{Formulation::minimal, Solver::bdf};
inline constexpr Integrator Integrator::arkode{Formulation::minimal, Solver::explicit_rk};
inline constexpr Integrator Integrator::ida{Formulation::index2, Solver::bdf};
inline constexpr Integrator Integrator::generalized_alpha{Formulation::index3, Solver::generalized_alpha};
inline constexpr Integrator Integrator::index1{Formulation::index1, Solver::bdf};
inline constexpr Integrator Integrator::baumgarte{Formulation::baumgarte, Solver::bdf};
inline constexpr Integrator Integrator::projection{Formulation::projection, Solver::bdf};

// A pair that is not implemented: names it and lists the valid pairs.
class InvalidIntegrator : public std::invalid_argument {
 public:
  explicit InvalidIntegrator(Integrator choice);
  Integrator choice() const { return choice_; }

 private:
  Integrator choice_;
};

// The name of a valid pair ("cvode"), or "FORMULATION×SOLVER" for one that is not.
std::string_view to_string(Integrator integrator);
std::optional<Integrator> parse_integrator(std::string_view text);  // a valid pair's name
std::string integrator_choices();  // "cvode|arkode|ida|generalized-alpha|index1|baumgarte|projection"
bool is_valid(Integrator integrator);
// The pair, or InvalidIntegrator.
Integrator integrator(Formulation formulation, Solver solver);
// "minimal × bdf (cvode), minimal × explicit-rk (arkode), ..." — every valid pair.
std::string valid_integrators();
// What the solver is called in messages: "CVODE", "IDA", "ARKODE ERK", "generalized-α", "CVODE (index1)".
std::string_view solver_label(Integrator integrator);

}  // namespace ffrf::solve
