// Newmark integration of the linear Cummins equation (see cummins_solver.hpp).
#include "hydro/cummins_solver.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace ffrf::hydro {

CumminsRecord integrate_cummins(const PlanarMatrix& mass, const PlanarMatrix& stiffness, RadiationModel& radiation,
                                const PlanarVector& x0, const PlanarVector& v0, double h, std::size_t steps,
                                const PlanarForce& force) {
  if (!(h > 0.0) || !std::isfinite(h)) throw std::invalid_argument(fmt::format("Cummins integration: step {} s; valid range > 0", h));
  if (const auto* conv = dynamic_cast<const ConvolutionRadiationModel*>(&radiation); conv && std::abs(conv->step() - h) > 1e-12 * h)
    throw std::invalid_argument(fmt::format(
        "Cummins integration: step {} s differs from the convolution kernel's sampling {} s; sample the kernel at the step",
        h, conv->step()));
  radiation.reset();
  auto external = [&](double t) { return force ? force(t) : PlanarVector::Zero(); };
  const PlanarMatrix inertia = mass + radiation.added_mass();
  const PlanarMatrix damping = radiation.current_damping();
  const Eigen::PartialPivLU<PlanarMatrix> effective(inertia + 0.5 * h * damping + 0.25 * h * h * stiffness);
  if (!(std::abs(effective.determinant()) > 0.0))
    throw std::invalid_argument("Cummins integration: the effective mass M + A + h/2 D + h²/4 C is singular");
  CumminsRecord record;
  PlanarVector x = x0, v = v0;
  // ẍ_0 from the equation at t = 0, the memory holding only ẋ_0.
  PlanarVector a = inertia.partialPivLu().solve(external(0.0) - radiation.memory_force(v) - stiffness * x);
  radiation.push(v);
  record.time.push_back(0.0);
  record.position.push_back(x);
  record.velocity.push_back(v);
  for (std::size_t n = 1; n <= steps; ++n) {
    const double t = static_cast<double>(n) * h;
    const PlanarVector x_predicted = x + h * v + 0.25 * h * h * a;
    const PlanarVector v_predicted = v + 0.5 * h * a;
    const PlanarVector rhs = external(t) - radiation.history_force() - damping * v_predicted - stiffness * x_predicted;
    a = effective.solve(rhs);
    x = x_predicted + 0.25 * h * h * a;
    v = v_predicted + 0.5 * h * a;
    radiation.push(v);
    record.time.push_back(t);
    record.position.push_back(x);
    record.velocity.push_back(v);
  }
  return record;
}

}  // namespace ffrf::hydro
