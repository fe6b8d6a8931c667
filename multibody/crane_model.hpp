// The crane's model and its equations, one name per role (Pinocchio's Model/Data, so threads share
// one model):
//  * CraneParameters<Coords> (multibody/crane_parameters.hpp): what the crane is — its bodies (hull,
//    boom over its elastic coordinates, cargo), its connectors (the heel joint, the wires), waters —
//    as built from a scene;
//  * CraneModel (here): the immutable model — the parameters and what follows from them alone (the
//    factorization of M_ff, M_ff⁻¹S̄ᵀ and M_ff⁻¹cᵀ, the Newton blocks' structure, the wire's tip
//    columns, coordinate scales), computed once by make_crane_model and shared by any number of
//    threads; implemented by CraneModelOf<Coords> (multibody/crane_model_of.hpp);
//  * CraneEquations (multibody/crane_equations.hpp): the equations on one workspace (what one
//    evaluation fills) and one run state (the radiation memory's history), made by
//    CraneModel::equations(); implemented by CraneEquationsOf<Coords>
//    (multibody/crane_equations_of.hpp: loads on the three bodies and the wires between them, the
//    minimal-coordinate ODE with the boom frame eliminated through the heel joint at B (a clamp, or a
//    pin that leaves the luffing angle) — velocity transformation q̇_B = J ż,
//    M_z = JᵀMJ, Q_z = Jᵀ(Q − M J̇ż); Shabana 2005 §6 — solved by a Schur complement on the constant
//    elastic mass M_ff, and the full-coordinate DAE pieces, paper eqs. 22, 31–34).
// scene/crane_builder.hpp makes each from a scene: build_crane_parameters, build_crane_model,
// build_crane_equations.
#pragma once

#include <memory>
#include <optional>

#include "multibody/crane_equations.hpp"
#include "multibody/crane_parameters.hpp"

namespace ffrf::multibody {

class CraneModel {
 public:
  virtual ~CraneModel() = default;
  // A new set of equations on this model: its own workspace and run state, no factorization redone.
  // Thread-safe (the model is read-only); each returned object belongs to one thread at a time.
  virtual std::unique_ptr<CraneEquations> equations() const = 0;
  virtual int elastic_size() const = 0;
  // The same crane — boom and its elastic coordinates, mount, cargo, wire — with another hull (its
  // hydrodynamics) and wave: a new model (this one unchanged) whose constants are derived again from
  // the copied coordinates (the boom's matrices, modes and projections are not rebuilt). The frequency
  // domain's one crane in a regular wave per frequency (study/rao.cpp).
  virtual std::shared_ptr<const CraneModel> in_waters(const HullModel& hull, const std::optional<sea::WaveField>& wave) const = 0;
};

// Computes the model's constant data (factorizes M_ff; throws std::runtime_error when it is not
// positive definite).
template <fem::ElasticCoordinates Coords>
std::shared_ptr<const CraneModel> make_crane_model(CraneParameters<Coords> model);

// make_crane_model(model)->equations(): a model used by one run alone.
template <fem::ElasticCoordinates Coords>
std::unique_ptr<CraneEquations> make_crane_equations(CraneParameters<Coords> model);

}  // namespace ffrf::multibody
