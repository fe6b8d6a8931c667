// Closed-form Euler–Bernoulli natural frequencies (see header). Bending roots βL are found by
// bisection of the scaled frequency equations cos β ± sech β = 0, which avoid cosh overflow;
// the n-th root is bracketed in ((n − 1)π, nπ) (clamped-free) or (nπ, (n + 1)π) (free-free).
#include "fem/analytic_beam.hpp"

#include <cmath>
#include <numbers>

namespace ffrf::fem {
namespace {

constexpr double pi = std::numbers::pi;

template <class Fn>
double bisect(Fn f, double lo, double hi) {
  double f_lo = f(lo);
  for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    const double f_mid = f(mid);
    if ((f_mid < 0.0) == (f_lo < 0.0)) {
      lo = mid;
      f_lo = f_mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

double bending_root(Boundary boundary, int n) {
  switch (boundary) {
    case Boundary::clamped_free:
      return bisect([](double b) { return std::cos(b) + 1.0 / std::cosh(b); }, (n - 1) * pi + 1e-12, n * pi);
    case Boundary::free_free:
      return bisect([](double b) { return std::cos(b) - 1.0 / std::cosh(b); }, n * pi, (n + 1) * pi);
    case Boundary::pinned_pinned: return n * pi;
  }
  return 0.0;
}

}  // namespace

std::string_view to_string(ModeKind kind) {
  switch (kind) {
    case ModeKind::rigid: return "rigid";
    case ModeKind::bending: return "bending";
    case ModeKind::axial: return "axial";
  }
  return "?";
}

std::vector<AnalyticMode> analytic_bending_modes(const BeamMesh& mesh, Boundary boundary, int count) {
  const BeamSection& s = mesh.section;
  const double scale = std::sqrt(s.bending_rigidity() / (s.mass_per_length * std::pow(mesh.length, 4)));
  std::vector<AnalyticMode> modes;
  for (int n = 1; n <= count; ++n) {
    const double beta_l = bending_root(boundary, n);
    modes.push_back({ModeKind::bending, n, beta_l * beta_l * scale, beta_l});
  }
  return modes;
}

std::vector<AnalyticMode> analytic_axial_modes(const BeamMesh& mesh, Boundary boundary, int count) {
  const BeamSection& s = mesh.section;
  const double wave_speed = std::sqrt(s.axial_rigidity() / s.mass_per_length);
  std::vector<AnalyticMode> modes;
  for (int n = 1; n <= count; ++n) {
    const double c = boundary == Boundary::free_free ? n * pi : (2 * n - 1) * pi / 2.0;
    modes.push_back({ModeKind::axial, n, c * wave_speed / mesh.length, c});
  }
  return modes;
}

int rigid_mode_count(Boundary boundary) { return boundary == Boundary::free_free ? 3 : 0; }

std::optional<double> euler_buckling_load(const BeamMesh& mesh, Boundary boundary) {
  const double euler = std::numbers::pi * std::numbers::pi * mesh.section.bending_rigidity() / (mesh.length * mesh.length);
  switch (boundary) {
    case Boundary::clamped_free: return euler / 4.0;
    case Boundary::pinned_pinned: return euler;
    case Boundary::free_free: return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace ffrf::fem
