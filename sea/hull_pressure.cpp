// Hydrostatic + Froude–Krylov pressure integral over the wetted boundary of a box hull section in
// closed form (see hull_pressure.hpp, docs/theory.md §6.2). On an edge r(s) = a + s d the incident
// pressure is a sum of terms c·e^{λ s} with complex λ = κ d_y + i k d_x (κ = ±k below still water,
// 0 for the crest extension) plus the linear hydrostatic part, so ∫p ds and ∫p s ds over a piece
// [s0, s0 + h] are elementary: c h φ1(λh) and c h² ψ(λh) with φ1(z) = (e^z − 1)/z and
// ψ(z) = ∫₀¹ v e^{zv} dv = (e^z (z − 1) + 1)/z² (power series for |z| < ½). Each piece is taken from
// the end with the larger Re(λ s), so no exponential exceeds 1. In deep water (and on every crest
// extension) the coefficients c_i and the e^{λ_i h} are phasors of the field (component_phasors.hpp: by
// recurrence on a harmonic grid, two complex products each instead of an exponential, sine and cosine),
// and the components inside the series radius are summed power by power (SeriesSums). Finite depth
// (two exponentials per component) keeps the direct formula. Waterline crossings:
// sea/waterline_crossings.hpp. No heap allocation.
#include "sea/hull_pressure.hpp"

#include <array>
#include <cmath>
#include <complex>
#include <sstream>
#include <stdexcept>

#include "sea/component_phasors.hpp"
#include "sea/hull_edges.hpp"
#include "sea/waterline_crossings.hpp"

namespace ffrf::sea {

namespace {

constexpr double series_radius = 0.5;
constexpr int series_terms = 18;  // |z|^18 / 18! < 1e-21 for |z| < ½

// 1/n! for the power series below.
constexpr std::array<double, series_terms> inverse_factorials() {
  std::array<double, series_terms> out{};
  double factorial = 1.0;
  for (int n = 0; n < series_terms; ++n) {
    if (n > 0) factorial *= n;
    out[static_cast<std::size_t>(n)] = 1.0 / factorial;
  }
  return out;
}
constexpr std::array<double, series_terms> inverse_factorial = inverse_factorials();

// Terms of the power series below for |z|² = size < ¼: enough that the first one left out, |z|ⁿ/n!, is
// below 1e-17: 8 for |z| < 0.01, 12 for |z| < 0.1, 14 for |z| < 0.25, else all (|z| < ½).
int series_term_count(double size) { return size < 1e-4 ? 8 : size < 1e-2 ? 12 : size < 0.0625 ? 14 : series_terms; }

// φ1(z) = (e^z − 1)/z and ψ(z) = (e^z (z − 1) + 1)/z² (∫₀¹ e^{zv} dv and ∫₀¹ v e^{zv} dv) by their
// power series for |z| < ½ (true), else false (use closed_moments).
bool series_moments(Complex z, Complex& phi1, Complex& psi) {
  const double size = std::norm(z);  // |z|²
  if (size >= series_radius * series_radius) return false;
  // φ1 = Σ zⁿ/(n+1)!, ψ = Σ zⁿ/(n! (n+2)), by Horner.
  const int terms = series_term_count(size);
  phi1 = 0.0;
  psi = 0.0;
  for (int n = terms - 2; n >= 0; --n) {
    phi1 = times(phi1, z) + inverse_factorial[static_cast<std::size_t>(n + 1)];
    psi = times(psi, z) + inverse_factorial[static_cast<std::size_t>(n)] / (n + 2);
  }
  return true;
}

// φ1 and ψ from e^z and 1/z (|z| ≥ ½, where the closed forms lose at most a few ulp to cancellation):
// φ1 = (e^z − 1)/z, ψ = (e^z (z − 1) + 1)/z² = (e^z − φ1)/z.
void closed_moments(Complex ez, Complex inverse_z, Complex& phi1, Complex& psi) {
  phi1 = times(ez - 1.0, inverse_z);
  psi = times(ez - phi1, inverse_z);
}

void exponential_moments(Complex z, Complex& phi1, Complex& psi) {
  if (series_moments(z, phi1, psi)) return;
  const double magnitude = std::exp(z.real());
  closed_moments(Complex(magnitude * std::cos(z.imag()), magnitude * std::sin(z.imag())), std::conj(z) / std::norm(z), phi1,
                 psi);
}

// Σ_i c_i φ1(z_i) and Σ_i c_i ψ(z_i) over components whose z_i = s_i ζ lie inside the series radius
// (0 ≤ s_i < 1, |ζ| = ½), by the power series summed over the components first:
//   Σ_i c_i φ1(z_i) = Σ_m ζ^m/(m+1)! Σ_i c_i s_i^m,   Σ_i c_i ψ(z_i) = Σ_m ζ^m/(m! (m+2)) Σ_i c_i s_i^m,
// four real operations per term and component instead of two complex Horner steps. Each component
// adds the terms its own |z_i| needs (as series_moments); the error stays ε Σ |c_i| e^{|z_i|}.
class SeriesSums {
 public:
  void add(Complex c, double s) {
    const int terms = series_term_count(0.25 * s * s);  // |z|² = (s/2)²
    for (int m = 0; m < terms - 1; ++m) {
      sums_[static_cast<std::size_t>(m)] += c;
      c *= s;
    }
  }
  // Adds the two sums at ζ to phi1_sum and psi_sum.
  void finish(Complex zeta, Complex& phi1_sum, Complex& psi_sum) const {
    Complex phi1 = 0.0, psi = 0.0;
    for (int m = series_terms - 2; m >= 0; --m) {
      const auto n = static_cast<std::size_t>(m);
      phi1 = times(phi1, zeta) + inverse_factorial[n + 1] * sums_[n];
      psi = times(psi, zeta) + inverse_factorial[n] / (m + 2) * sums_[n];
    }
    phi1_sum += phi1;
    psi_sum += psi;
  }

 private:
  std::array<Complex, series_terms> sums_{};
};

// Adds Re ∫₀ʰ c e^{λu} du and Re ∫₀ʰ u c e^{λu} du for c = amplitude·e^{κ y0 + offset + iθ0},
// λ = κ d_y + i k d_x.
void add_exponential(double amplitude, double kappa, double offset, double k, double theta0, double y0,
                     const Eigen::Vector2d& d, double h, PieceIntegrals& out) {
  Complex lambda(kappa * d.y(), k * d.x());
  const bool from_end = lambda.real() > 0.0;  // integrate from the end with the larger exponent
  const double y_ref = from_end ? y0 + h * d.y() : y0;
  const double theta_ref = from_end ? theta0 + h * k * d.x() : theta0;
  if (from_end) lambda = -lambda;
  const double magnitude = amplitude * std::exp(kappa * y_ref + offset);
  const Complex c(magnitude * std::cos(theta_ref), magnitude * std::sin(theta_ref));
  Complex phi1, psi;
  exponential_moments(lambda * h, phi1, psi);
  const double i0 = h * (c * phi1).real();
  const double i1 = h * h * (c * psi).real();
  out.j0 += i0;
  out.j1 += from_end ? h * i0 - i1 : i1;  // u = h − v on the reversed piece
}

// Deep water: adds the incident-wave part of ∫ p/(ρg) over [s0, s0 + h] for all components at once,
// each term c_i e^{λ_i u} with c_i = r a_i e^{k_i (κ̂ y + i x) + i(φ_i − δ ω_i t)} at the reference end and
// λ_i h = k_i w, w = ±(κ̂ d_y + i d_x) h (κ̂ = 1 below still water, 0 on the crest extension): both are
// phasors e^{k_i z} of the field (component_phasors.hpp), by recurrence on a harmonic grid.
void add_deep_water_terms(const WaveField& wave, double t, double ramp, bool airy, const HullEdge& edge, double s0,
                          double h, PieceIntegrals& out) {
  const double decay = airy ? 1.0 : 0.0;
  const bool from_end = airy && edge.d.y() > 0.0;  // integrate from the end with the larger exponent
  const Eigen::Vector2d reference = edge.a + (from_end ? s0 + h : s0) * edge.d;
  const Complex w = (from_end ? -h : h) * Complex(decay * edge.d.y(), edge.d.x());
  ComponentPhasors value(wave, Complex(decay * reference.y(), reference.x()), t), growth(wave, w, 0.0);
  const std::vector<WaveComponent>& components = wave.components();
  const std::vector<Complex>& amplitudes = wave.complex_amplitudes();
  // z_i = k_i w = s_i ζ with |ζ| = ½: s_i < 1 inside the series radius.
  const double w_size = std::abs(w), to_series = w_size / series_radius;
  const Complex zeta = w_size > 0.0 ? w / to_series : Complex(0.0);
  const Complex inverse_w = w_size > 0.0 ? std::conj(w) / std::norm(w) : Complex(0.0);  // 1/z_i = (1/w)/k_i
  SeriesSums series;
  Complex phi1_sum = 0.0, psi_sum = 0.0;  // Σ c φ1(λh), Σ c ψ(λh) without r
  for (std::size_t i = 0; i < components.size(); ++i) {
    const Complex c = times(amplitudes[i], value.next());
    const Complex exponential = growth.next();
    const double s = components[i].wave_number * to_series;
    if (s < 1.0) {
      series.add(c, s);
      continue;
    }
    Complex phi1, psi;
    closed_moments(exponential, inverse_w / components[i].wave_number, phi1, psi);
    phi1_sum += times(c, phi1);
    psi_sum += times(c, psi);
  }
  series.finish(zeta, phi1_sum, psi_sum);
  const double sum0 = phi1_sum.real(), sum1 = psi_sum.real();
  const double i0 = ramp * h * sum0, i1 = ramp * h * h * sum1;
  out.j0 += i0;
  out.j1 += from_end ? h * i0 - i1 : i1;  // u = h − v on the reversed piece
}

// ∫ p/(ρg) over the wetted piece [s0, s1] of an edge, below (airy) or above still water.
PieceIntegrals piece_integrals(const WaveField* wave, double t, const HullEdge& edge, double s0, double s1, bool airy) {
  const double h = s1 - s0;
  const double y0 = edge.a.y() + s0 * edge.d.y();
  PieceIntegrals out = hydrostatic_piece(edge, s0, h);
  if (wave == nullptr) return out;
  const double ramp = wave->ramp(t);
  if (ramp == 0.0) return out;
  if (wave->deep() || !airy) {
    add_deep_water_terms(*wave, t, ramp, airy, edge, s0, h, out);
    return out;
  }
  const double x0 = edge.a.x() + s0 * edge.d.x();
  const double depth = wave->depth();
  for (const WaveComponent& c : wave->components()) {  // cosh(k(y + d))/cosh(kd) = (e^{ky} + e^{−k(y + 2d)}) / (1 + e^{−2kd})
    const double k = c.wave_number;
    const double theta0 = k * x0 - wave->direction() * c.angular_frequency * t + c.phase;
    const double scale = ramp * c.amplitude / (1.0 + std::exp(-2.0 * k * depth));
    add_exponential(scale, k, 0.0, k, theta0, y0, edge.d, h, out);
    add_exponential(scale, -k, -2.0 * k * depth, k, theta0, y0, edge.d, h, out);
  }
  return out;
}

// Wetted interval [s0, s1]: split where y(s) = 0 (p changes formula there), then integrate.
void integrate_wetted(const WaveField* wave, double t, const HullEdge& edge, const Eigen::Vector2d& g1, double s0,
                      double s1, EdgeMoments& acc) {
  if (!(s1 > s0)) return;
  acc.wetted_length += (s1 - s0) * edge.length;
  std::array<double, 3> cuts = {s0, s1, s1};
  int pieces = 1;
  if (edge.d.y() != 0.0) {
    const double s_still = -edge.a.y() / edge.d.y();
    if (s_still > s0 && s_still < s1) {
      cuts = {s0, s_still, s1};
      pieces = 2;
    }
  }
  for (int i = 0; i < pieces; ++i) {
    const double lo = cuts[static_cast<std::size_t>(i)], hi = cuts[static_cast<std::size_t>(i + 1)];
    const bool airy = edge.a.y() + 0.5 * (lo + hi) * edge.d.y() <= 0.0;
    add_piece(edge, g1, lo, piece_integrals(wave, t, edge, lo, hi, airy), acc);
  }
}

EdgeMoments edge_moments(const WaveField* wave, double t, const HullEdge& edge, const Eigen::Vector2d& g1) {
  EdgeMoments acc;
  const double ya = edge.a.y(), yb = edge.a.y() + edge.d.y();
  const double bound = wave ? wave->elevation_bound(t) : 0.0;
  if (std::max(ya, yb) < -bound) {  // wholly below the troughs: wet
    integrate_wetted(wave, t, edge, g1, 0.0, 1.0, acc);
    return acc;
  }
  if (std::min(ya, yb) > bound) return acc;  // wholly above the crests: dry
  if (bound == 0.0) {  // calm water (or not yet ramped in): y(s) is linear, the crossing is exact
    if (ya >= 0.0 && yb >= 0.0) return acc;
    if (ya < 0.0 && yb < 0.0) {
      integrate_wetted(wave, t, edge, g1, 0.0, 1.0, acc);
    } else {
      const double s_cross = ya / (ya - yb);
      if (ya < 0.0) integrate_wetted(wave, t, edge, g1, 0.0, s_cross, acc);
      else integrate_wetted(wave, t, edge, g1, s_cross, 1.0, acc);
    }
    return acc;
  }
  const WaterlineCrossings crossings = waterline_crossings(*wave, t, edge.a, edge.d);
  if (crossings.truncated) {
    throw std::domain_error("hull_pressure_load: more than " + std::to_string(WaterlineCrossings::max_crossings) +
                            " waterline crossings on one hull edge (wave components far shorter than the hull)");
  }
  bool wet = crossings.wet_at_start;
  double wet_start = 0.0;
  for (int i = 0; i < crossings.count; ++i) {
    const double s = crossings.s[static_cast<std::size_t>(i)];
    if (wet) integrate_wetted(wave, t, edge, g1, wet_start, s, acc);
    else wet_start = s;
    wet = !wet;
  }
  if (wet) integrate_wetted(wave, t, edge, g1, wet_start, 1.0, acc);
  return acc;
}

void check_box(const BoxHullSection& hull) {
  if (!(hull.fore_x > hull.aft_x) || !(hull.deck_y > hull.keel_y) || !(hull.width > 0.0) ||
      !std::isfinite(hull.fore_x - hull.aft_x) || !std::isfinite(hull.deck_y - hull.keel_y) ||
      !std::isfinite(hull.width))
    throw std::invalid_argument("BoxHullSection: need aft_x < fore_x, keel_y < deck_y, width > 0, all finite");
}

}  // namespace

HullLoad hull_pressure_load(const BoxHullSection& hull, const WaveField* wave, double water_density,
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
  if (wave && !(std::abs(wave->gravity() - gravity) <= 1e-12 * gravity))
    throw std::invalid_argument("hull_pressure_load: the wave's gravity differs from the system's");

  const double rho_g = water_density * gravity;
  HullLoad load;
  for (const HullEdge& edge : hull_edges(hull, g1_position, pitch))
    add_edge_load(hull, edge, edge_moments(wave, t, edge, g1_position), rho_g, load);
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

}  // namespace ffrf::sea
