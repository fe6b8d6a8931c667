// The linear Cummins equation of a hull alone, stepped at a fixed step by Newmark's average-
// acceleration rule (β = 1/4, γ = 1/2: unconditionally stable, second order, no numerical damping;
// period error (ωh)²/12): (M + A_model) ẍ + μ(ẋ history) + C x = F(t), with μ from one of the
// radiation models (radiation_models.hpp). Used for free decays and regular-wave checks against
// the frequency domain, and as the benchmark's step (docs/hydrodynamics.md §3.5).
#pragma once

#include <functional>
#include <vector>

#include "hydro/radiation_models.hpp"

namespace ffrf::hydro {

struct CumminsRecord {
  std::vector<double> time;
  std::vector<PlanarVector> position, velocity;
};

using PlanarForce = std::function<PlanarVector(double t)>;

// Starts from x0, ẋ0 (the model is reset: at rest before t = 0, so ẋ0 should be 0 for a memory
// model), steps `steps` times by h (must equal the convolution model's step). Throws
// std::invalid_argument on h ≤ 0, a step that differs from the convolution's, or a singular
// effective mass.
CumminsRecord integrate_cummins(const PlanarMatrix& mass, const PlanarMatrix& stiffness, RadiationModel& radiation,
                                const PlanarVector& x0, const PlanarVector& v0, double step, std::size_t steps,
                                const PlanarForce& force = nullptr);

}  // namespace ffrf::hydro
