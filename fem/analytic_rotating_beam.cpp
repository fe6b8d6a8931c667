// Frobenius power series of the rotating clamped-free beam and the tip determinant (see header).
// Convergence: the series is summed until four consecutive terms of every tip sum fall below
// 1e-22 of the largest partial sum; long double keeps the cancellation between the growing terms
// (∼ e^{(μ+κλ)^{1/4}} for the third mode) far above the wanted 1e-12.
#include "fem/analytic_rotating_beam.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace ffrf::fem {
namespace {

constexpr int max_terms = 6000;

struct TipValues {
  long double slope, curvature, shear;  // V'(1), V''(1), V'''(1)
};

// One series solution with c₂, c₃ given; returns its tip values.
TipValues tip_values(const RotatingBeamProblem& p, long double mu, long double c2, long double c3) {
  const long double lambda = p.spin_parameter;
  const long double s = p.centrifugal_stiffening ? 1.0L : 0.0L;
  const long double n0 = s * lambda * (p.hub_radius_ratio + 0.5L) + p.axial_force_parameter;
  const long double n1 = -s * lambda * p.hub_radius_ratio;
  const long double n2 = -0.5L * s * lambda;
  const long double eigen = mu + (p.in_plane ? lambda : 0.0L);
  // Ring buffer of c_k .. c_{k+3}.
  long double c[4] = {0.0L, 0.0L, c2, c3};
  TipValues tip{2.0L * c2 + 3.0L * c3, 2.0L * c2 + 6.0L * c3, 6.0L * c3};  // the ξ², ξ³ terms
  long double largest = std::fabs(tip.slope) + std::fabs(tip.curvature) + std::fabs(tip.shear);
  int small_in_a_row = 0;
  for (int k = 0; k + 4 < max_terms; ++k) {
    const long double kk = k;
    const long double ck = c[0], ck1 = c[1], ck2 = c[2];
    const long double next = ((kk + 1) * (n0 * (kk + 2) * ck2 + n1 * (kk + 1) * ck1 + n2 * kk * ck) + eigen * ck) /
                             ((kk + 1) * (kk + 2) * (kk + 3) * (kk + 4));
    c[0] = c[1];
    c[1] = c[2];
    c[2] = c[3];
    c[3] = next;
    const long double n = kk + 4;
    const long double d1 = n * next, d2 = n * (n - 1) * next, d3 = n * (n - 1) * (n - 2) * next;
    tip.slope += d1;
    tip.curvature += d2;
    tip.shear += d3;
    largest = std::fmax(largest, std::fabs(tip.slope) + std::fabs(tip.curvature) + std::fabs(tip.shear));
    const bool small = std::fabs(d1) + std::fabs(d2) + std::fabs(d3) <= 1e-22L * largest;
    small_in_a_row = small && k > 8 ? small_in_a_row + 1 : 0;
    if (small_in_a_row >= 4) return tip;
  }
  throw std::runtime_error("rotating-beam power series did not converge in " + std::to_string(max_terms) +
                           " terms (mu = " + std::to_string(static_cast<double>(mu)) + ")");
}

void validate(const RotatingBeamProblem& p) {
  const auto bad = [](const char* name, double value, const char* range) {
    throw std::invalid_argument(std::string(name) + " = " + std::to_string(value) + " is outside the valid range " + range);
  };
  if (!std::isfinite(p.spin_parameter) || p.spin_parameter < 0.0) bad("spin parameter lambda", p.spin_parameter, "[0, inf)");
  if (!std::isfinite(p.hub_radius_ratio) || p.hub_radius_ratio < 0.0) bad("hub radius ratio r/L", p.hub_radius_ratio, "[0, inf)");
  if (!std::isfinite(p.axial_force_parameter)) bad("axial force parameter P L^2/EI", p.axial_force_parameter, "(-pi^2/4, inf)");
}

}  // namespace

double rotating_beam_frequency_scale(const BeamMesh& mesh) {
  const BeamSection& s = mesh.section;
  return std::sqrt(s.bending_rigidity() / (s.mass_per_length * std::pow(mesh.length, 4)));
}

RotatingBeamProblem rotating_beam_problem(const BeamMesh& mesh, double spin_rate, double hub_radius, double axial_force,
                                          bool centrifugal_stiffening) {
  const double scale = rotating_beam_frequency_scale(mesh);
  RotatingBeamProblem p;
  p.spin_parameter = spin_rate * spin_rate / (scale * scale);
  p.hub_radius_ratio = hub_radius / mesh.length;
  p.axial_force_parameter = axial_force * mesh.length * mesh.length / mesh.section.bending_rigidity();
  p.centrifugal_stiffening = centrifugal_stiffening;
  p.in_plane = true;
  return p;
}

long double rotating_beam_tip_determinant(const RotatingBeamProblem& problem, long double mu) {
  const TipValues a = tip_values(problem, mu, 1.0L, 0.0L);
  const TipValues b = tip_values(problem, mu, 0.0L, 1.0L);
  const long double tip_force = problem.axial_force_parameter;  // n(1): the centrifugal part vanishes at the tip
  const long double a_shear = a.shear - tip_force * a.slope;
  const long double b_shear = b.shear - tip_force * b.slope;
  return a.curvature * b_shear - b.curvature * a_shear;
}

std::vector<double> rotating_beam_eigenvalues(const RotatingBeamProblem& problem, int count) {
  validate(problem);
  if (count < 1) throw std::invalid_argument("mode count " + std::to_string(count) + " must be >= 1");
  const double buckling = std::numbers::pi * std::numbers::pi / 4.0;
  if (problem.axial_force_parameter <= -buckling) {
    throw std::domain_error("P L^2/EI = " + std::to_string(problem.axial_force_parameter) +
                            " is at or beyond the buckling load -pi^2/4: the beam is buckled, no reference");
  }
  // Scan t = √(μ + κλ) > 0 (the flapwise-equivalent operator is positive definite below buckling,
  // and the tension only adds to it); roots are simple and at least ~2 apart in t.
  const long double offset = problem.in_plane ? problem.spin_parameter : 0.0;
  const auto determinant = [&](long double t) { return rotating_beam_tip_determinant(problem, t * t - offset); };
  std::vector<double> eigenvalues;
  const long double step = 0.05L;
  long double lo = 1e-6L;
  long double d_lo = determinant(lo);
  for (int i = 0; static_cast<int>(eigenvalues.size()) < count; ++i) {
    if (i > 200000) throw std::runtime_error("rotating-beam eigenvalue scan found too few roots");
    const long double hi = lo + step;
    const long double d_hi = determinant(hi);
    if ((d_lo < 0) != (d_hi < 0)) {
      long double a = lo, b = hi, d_a = d_lo;
      for (int it = 0; it < 200 && b - a > 1e-18L * b; ++it) {
        const long double mid = 0.5L * (a + b);
        const long double d_mid = determinant(mid);
        if ((d_mid < 0) == (d_a < 0)) {
          a = mid;
          d_a = d_mid;
        } else {
          b = mid;
        }
      }
      const long double t = 0.5L * (a + b);
      eigenvalues.push_back(static_cast<double>(t * t - offset));
    }
    lo = hi;
    d_lo = d_hi;
  }
  return eigenvalues;
}

}  // namespace ffrf::fem
