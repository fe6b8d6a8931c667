// The boom's free-free vibration modes taken in the heel's tangent frame: each elastic mode of the
// unsupported beam, K φ = ω² M φ on all DOFs, less the rigid motion that moves its root node,
//   φ_t = φ − u₀ e_u − v₀ e_v − φ₀ r,   r: the turn about the root (u = 0, v = x, θ = 1 at each node),
// so u(0) = v(0) = θ(0) = 0 (the tangent frame's reference condition, docs/theory.md §7.5); then a
// Rayleigh–Ritz step in their span (Eigen's generalized self-adjoint solver on φ_tᵀKφ_t, φ_tᵀMφ_t)
// makes the columns M-orthonormal and K-orthogonal. The rigid motion changes no strain, so the span
// of the frame's rigid motion and these shapes is the span of the rigid and elastic free-free modes:
// the same deformations, described from a frame at the heel rather than the mean axis.
#pragma once

#include "fem/beam_model.hpp"
#include "modal/eigen_solver.hpp"
#include "modal/mode_cache.hpp"

namespace ffrf::modal {

// The k lowest elastic free-free modes of the beam's mesh in the tangent frame, on the DOFs of
// `tangent_beam` (its boundary must be clamped-free; columns M-orthonormal in its mass, eigenvalues
// the Ritz values ω² of their span, ascending). `cache` solves the free-free eigenproblem (shifted
// below the rigid modes). Throws EigenSolverError.
EigenPairs free_free_modes_in_tangent_frame(const fem::BeamModel& tangent_beam, int k, EigenSolverKind solver, ModeCache& cache);

}  // namespace ffrf::modal
