// Hydrostatic + Froude–Krylov pressure integral over the wetted boundary of a box hull section
// (see hull_pressure.hpp, docs/theory.md §6). Each of the four edges r(s) = a + s (b − a) is
// wetted where y(s) < ζ(x(s), t); crossings are bracketed by 64 samples and refined by bisection,
// and each wetted interval is split at y = 0 (where p changes formula) and into pieces ≤ 5 m
// integrated by 8-point Gauss–Legendre. No heap allocation on the success path.
#include "coupling/hull_pressure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace ffrf::coupling {

namespace {

constexpr int samples_per_edge = 64;
constexpr double bisection_tolerance = 1e-13;  // in the edge parameter s ∈ [0, 1]
constexpr double max_piece_length = 5.0;       // [m]

// 8-point Gauss–Legendre on [−1, 1]: ± nodes and weights (exact for degree 15).
constexpr std::array<double, 4> gauss_node = {0.18343464249564980494, 0.52553240991632898582,
                                              0.79666647741362673959, 0.96028985649753623168};
constexpr std::array<double, 4> gauss_weight = {0.36268378337836198297, 0.31370664587788728734,
                                                0.22238103445337447054, 0.10122853629037625915};

// What one evaluation needs: the wave (or calm water) and the reference point G1.
struct PressureField {
  const AiryWave* wave;
  double density;
  double gravity;
  double t;

  double surface(double x) const { return wave ? wave->elevation(x, t) : 0.0; }
  double pressure(const Eigen::Vector2d& r) const {
    if (wave) return wave->pressure(r.x(), r.y(), t, density);
    return r.y() < 0.0 ? -density * gravity * r.y() : 0.0;
  }
  bool wet(const Eigen::Vector2d& r) const { return r.y() < surface(r.x()); }
};

// Running pressure moments of one edge: ∫ p ds and ∫ p (r − r_G1) ds.
struct EdgeMoments {
  double p0 = 0.0;
  Eigen::Vector2d p1 = Eigen::Vector2d::Zero();
  double wetted_length = 0.0;
};

void integrate_piece(const PressureField& field, const Eigen::Vector2d& a, const Eigen::Vector2d& d,
                     const Eigen::Vector2d& g1, double length, double s0, double s1, EdgeMoments& acc) {
  const double piece = (s1 - s0) * length;
  if (!(piece > 0.0)) return;
  const int count = static_cast<int>(std::ceil(piece / max_piece_length));
  const double h = (s1 - s0) / count;
  for (int j = 0; j < count; ++j) {
    const double mid = s0 + (j + 0.5) * h;
    for (std::size_t i = 0; i < gauss_node.size(); ++i) {
      for (const double sign : {-1.0, 1.0}) {
        const Eigen::Vector2d r = a + (mid + sign * 0.5 * h * gauss_node[i]) * d;
        const double w = gauss_weight[i] * 0.5 * h * length * field.pressure(r);
        acc.p0 += w;
        acc.p1 += w * (r - g1);
      }
    }
  }
}

// Wetted interval [s0, s1] of an edge: split where y(s) = 0 (p is only C⁰ there, the dynamic part
// switches from the Airy decay to the hydrostatic extension), then integrate.
void integrate_wetted(const PressureField& field, const Eigen::Vector2d& a, const Eigen::Vector2d& d,
                      const Eigen::Vector2d& g1, double length, double s0, double s1, EdgeMoments& acc) {
  acc.wetted_length += (s1 - s0) * length;
  if (d.y() != 0.0) {
    const double s_still = -a.y() / d.y();
    if (s_still > s0 && s_still < s1) {
      integrate_piece(field, a, d, g1, length, s0, s_still, acc);
      integrate_piece(field, a, d, g1, length, s_still, s1, acc);
      return;
    }
  }
  integrate_piece(field, a, d, g1, length, s0, s1, acc);
}

// Bisection on [lo, hi] where wet(lo) == lo_wet != wet(hi).
double crossing(const PressureField& field, const Eigen::Vector2d& a, const Eigen::Vector2d& d, double lo,
                double hi, bool lo_wet) {
  while (hi - lo > bisection_tolerance) {
    const double mid = 0.5 * (lo + hi);
    (field.wet(a + mid * d) == lo_wet ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

EdgeMoments edge_moments(const PressureField& field, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                         const Eigen::Vector2d& g1) {
  EdgeMoments acc;
  const Eigen::Vector2d d = b - a;
  const double length = d.norm();
  if (!field.wave) {  // calm water: y(s) is linear, the waterline crossing is exact
    const double ya = a.y(), yb = b.y();
    if (ya >= 0.0 && yb >= 0.0) return acc;
    if (ya < 0.0 && yb < 0.0) {
      integrate_wetted(field, a, d, g1, length, 0.0, 1.0, acc);
    } else {
      const double s_cross = ya / (ya - yb);
      if (ya < 0.0) integrate_wetted(field, a, d, g1, length, 0.0, s_cross, acc);
      else integrate_wetted(field, a, d, g1, length, s_cross, 1.0, acc);
    }
    return acc;
  }
  // |ζ| ≤ ζ_a r(t): an edge wholly below the troughs is wet, one wholly above the crests is dry.
  const double bound = std::abs(field.wave->amplitude * field.wave->ramp(field.t));
  if (std::max(a.y(), b.y()) < -bound) {
    integrate_wetted(field, a, d, g1, length, 0.0, 1.0, acc);
    return acc;
  }
  if (std::min(a.y(), b.y()) > bound) return acc;
  double prev_s = 0.0, wet_start = 0.0;
  bool prev_wet = field.wet(a);
  for (int i = 1; i <= samples_per_edge; ++i) {
    const double s = static_cast<double>(i) / samples_per_edge;
    const bool wet = field.wet(a + s * d);
    if (wet != prev_wet) {
      const double root = crossing(field, a, d, prev_s, s, prev_wet);
      if (wet) wet_start = root;
      else integrate_wetted(field, a, d, g1, length, wet_start, root, acc);
    }
    prev_s = s;
    prev_wet = wet;
  }
  if (prev_wet) integrate_wetted(field, a, d, g1, length, wet_start, 1.0, acc);
  return acc;
}

void check_box(const BoxHullSection& hull) {
  if (!(hull.fore_x > hull.aft_x) || !(hull.deck_y > hull.keel_y) || !(hull.width > 0.0) ||
      !std::isfinite(hull.fore_x - hull.aft_x) || !std::isfinite(hull.deck_y - hull.keel_y) ||
      !std::isfinite(hull.width))
    throw std::invalid_argument("BoxHullSection: need aft_x < fore_x, keel_y < deck_y, width > 0, all finite");
}

}  // namespace

HullLoad hull_pressure_load(const BoxHullSection& hull, const AiryWave* wave, double water_density,
                            double gravity, const Eigen::Vector2d& g1_position, double pitch, double t) {
  if (!g1_position.allFinite() || !std::isfinite(pitch) || !std::isfinite(t)) {
    std::ostringstream message;
    message.precision(17);
    message << "hull_pressure_load: non-finite pose x = " << g1_position.x() << ", y = " << g1_position.y()
            << ", theta = " << pitch << " at t = " << t;
    throw std::domain_error(message.str());
  }
  check_box(hull);
  if (!(water_density > 0.0) || !(gravity > 0.0) || !std::isfinite(water_density) || !std::isfinite(gravity))
    throw std::invalid_argument("hull_pressure_load: water density and gravity must be finite and > 0");
  if (wave && !(std::abs(wave->gravity - gravity) <= 1e-12 * gravity))
    throw std::invalid_argument("hull_pressure_load: the wave's gravity differs from the system's");

  const PressureField field{wave, water_density, gravity, t};
  const double c = std::cos(pitch), s = std::sin(pitch);
  const auto place = [&](double x, double y) { return Eigen::Vector2d(g1_position.x() + c * x - s * y, g1_position.y() + s * x + c * y); };
  // Counter-clockwise: keel aft → keel fore → deck fore → deck aft; outward normal = (d_y, −d_x)/|d|.
  const std::array<Eigen::Vector2d, 4> corner = {place(hull.aft_x, hull.keel_y), place(hull.fore_x, hull.keel_y),
                                                 place(hull.fore_x, hull.deck_y), place(hull.aft_x, hull.deck_y)};
  HullLoad load;
  for (std::size_t e = 0; e < corner.size(); ++e) {
    const Eigen::Vector2d& a = corner[e];
    const Eigen::Vector2d& b = corner[(e + 1) % corner.size()];
    const EdgeMoments m = edge_moments(field, a, b, g1_position);
    if (m.wetted_length == 0.0) continue;
    const Eigen::Vector2d d = b - a;
    const Eigen::Vector2d n = Eigen::Vector2d(d.y(), -d.x()) / d.norm();
    load.force -= hull.width * m.p0 * n;
    load.moment -= hull.width * (m.p1.x() * n.y() - m.p1.y() * n.x());
    load.wetted_length += m.wetted_length;
  }
  return load;
}

Eigen::Vector2d box_hydrostatic_stiffness(const BoxHullSection& hull, double water_density, double gravity,
                                          double displaced_volume, double center_of_gravity_above_keel) {
  check_box(hull);
  const double length = hull.fore_x - hull.aft_x;
  const double draft = displaced_volume / (hull.width * length);
  if (!(displaced_volume > 0.0) || !(draft < hull.deck_y - hull.keel_y))
    throw std::invalid_argument("box_hydrostatic_stiffness: need 0 < displaced volume < box volume");
  const double rho_g = water_density * gravity;
  const double waterplane_inertia = hull.width * length * length * length / 12.0;  // about mid-length
  const double buoyancy_center_above_keel = 0.5 * draft;
  return {rho_g * hull.width * length,
          rho_g * (waterplane_inertia + displaced_volume * (buoyancy_center_above_keel - center_of_gravity_above_keel))};
}

}  // namespace ffrf::coupling
