// The floating crane's equations of motion for one choice of elastic coordinates: loads on the
// three bodies (gravity, hull pressure, radiation, mooring, wire, elastic and damping forces),
// the minimal-coordinate ODE (boom frame eliminated through the clamp at B, velocity
// transformation q̇_B = J ż, M_z = JᵀMJ, Q_z = Jᵀ(Q − M J̇ż); Shabana 2005 §6, "embedding
// technique") solved by a Schur complement on the constant elastic mass M_ff, and the full-
// coordinate DAE pieces (paper eqs. 22, 31–34). Implements CraneEquations.
// Model and workspace apart (Pinocchio's Model/Data, so threads share one model): a SharedCraneModel is the
// immutable part — the CraneModel and what follows from it alone (the factorization of M_ff,
// M_ff⁻¹S̄ᵀ and M_ff⁻¹cᵀ, the Newton blocks' structure, the wire's tip columns, coordinate scales) —
// computed once and shared by any number of threads; each CraneEquations it makes owns a small
// workspace (what one evaluation fills) and the run state (the radiation memory's history).
#pragma once

#include <memory>
#include <optional>

#include "multibody/crane_equations.hpp"
#include "multibody/crane_model.hpp"

namespace ffrf::multibody {

class SharedCraneModel {
 public:
  virtual ~SharedCraneModel() = default;
  // A new set of equations on this model: its own workspace and run state, no factorization redone.
  // Thread-safe (the model is read-only); each returned object belongs to one thread at a time.
  virtual std::unique_ptr<CraneEquations> equations() const = 0;
  virtual int elastic_size() const = 0;
  // The same crane — boom and its elastic coordinates, mount, cargo, wire — with another hull (its
  // hydrodynamics) and wave: a new model (this one unchanged) whose constants are derived again from
  // the copied coordinates (the boom's matrices, modes and projections are not rebuilt). The frequency
  // domain's one crane in a regular wave per frequency (study/rao.cpp).
  virtual std::shared_ptr<const SharedCraneModel> in_waters(const HullModel& hull, const std::optional<sea::WaveField>& wave) const = 0;
};

// Computes the model's constant data (factorizes M_ff; throws std::runtime_error when it is not
// positive definite).
template <fem::ElasticCoordinates Coords>
std::shared_ptr<const SharedCraneModel> make_shared_crane_model(CraneModel<Coords> model);

// make_shared_crane_model(model)->equations(): a model used by one run alone.
template <fem::ElasticCoordinates Coords>
std::unique_ptr<CraneEquations> make_crane_equations(CraneModel<Coords> model);

}  // namespace ffrf::multibody
