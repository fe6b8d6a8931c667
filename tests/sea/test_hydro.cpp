// Regular wave field and box-hull pressure load against independent references derived here: dispersion
// residual and deep-water wavelength, ramp, Archimedes on clipped polygons (shoelace), hydrostatic
// stiffness by finite differences, Froude–Krylov closed forms on submerged boxes (deep and finite
// depth) and on a floating box whose deck is overtopped, the long-wave limit, allocation-free
// evaluation, dry hull and non-finite poses.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "sea/hull_pressure.hpp"
#include "sea/wave_field.hpp"

// Global allocation counter (this executable only; off unless a test turns it on): hull_pressure_load
// must not allocate.
namespace hydro_test {
long allocation_count = 0;
bool counting_allocations = false;
}  // namespace hydro_test
void* operator new(std::size_t size) {
  if (hydro_test::counting_allocations) ++hydro_test::allocation_count;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
// The replacements pair malloc with free, as they must; inlined into a caller, GCC 12 at -O1 sees only
// `operator new` on one side and `free` on the other and reports -Wmismatched-new-delete (a false
// positive for a replaced allocation function).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace hydro_test {

using namespace ffrf::sea;
using Eigen::Vector2d;
constexpr double rho = 1025.0, g = 9.81, pi = std::numbers::pi;
const double deep = std::numeric_limits<double>::infinity();
// The reference hull (docs/architecture.md, "The reference scene"): 90 m × 40 m × 8 m box, G1 6 m above the keel and 13 m aft of mid-length.
const BoxHullSection hull{-32.0, 58.0, -6.0, 2.0, 40.0};
constexpr double L = 90.0, B = 40.0, x_f = 13.0;

// The one component of a regular wave.
const WaveComponent& only(const WaveField& w) { return w.components().at(0); }
double wavelength(const WaveField& w) { return 2.0 * pi / only(w).wave_number; }

HullLoad load(const WaveField* wave, double x, double y, double theta, double t, const BoxHullSection& h = hull) {
  return hull_pressure_load(h, wave, rho, g, Vector2d(x, y), theta, t);
}

// ---------------------------------------------------------------------------------- the wave ----

TEST(RegularWave, DeepWaterWavelengthIsGTSquaredOverTwoPi) {
  const auto w = WaveField::regular(1.0, 10.0, 1.0, 2.0, deep, g);
  EXPECT_NEAR(wavelength(w), g * 100.0 / (2.0 * pi), 1e-12 * 156.0);
  EXPECT_NEAR(wavelength(w), 156.13, 5e-3);
  EXPECT_DOUBLE_EQ(only(w).amplitude, 0.5);
  EXPECT_DOUBLE_EQ(w.ramp_duration(), 20.0);
  EXPECT_NEAR(2.0 * pi / only(w).angular_frequency, 10.0, 1e-14);
  EXPECT_EQ(only(w).phase, 0.0);
}

TEST(RegularWave, FiniteDepthDispersionToMachinePrecision) {
  for (const double d : {0.5, 5.0, 20.0, 60.0, 400.0, 1e5}) {
    for (const double period : {2.0, 6.0, 10.0, 25.0, 200.0}) {
      const auto w = WaveField::regular(1.0, period, -1.0, 0.0, d, g);
      const double omega2 = only(w).angular_frequency * only(w).angular_frequency;
      const double residual = omega2 - g * only(w).wave_number * std::tanh(only(w).wave_number * d);
      EXPECT_LE(std::abs(residual), 1e-14 * omega2) << "d = " << d << ", T = " << period;
      // Finite depth shortens the wave: k ≥ max(ω²/g, ω/√(g d)) (tanh x < 1, tanh x ≤ x).
      EXPECT_GE(only(w).wave_number, std::max(omega2 / g, only(w).angular_frequency / std::sqrt(g * d)) * (1 - 1e-15));
    }
  }
  // Deep limit and shallow limit (k d → 0: c = √(g d) to O((kd)²)).
  EXPECT_NEAR(WaveField::wave_number_from_dispersion(0.6, 1e4, g), 0.36 / g, 1e-16);
  const double k_shallow = WaveField::wave_number_from_dispersion(0.01, 1.0, g), nu = 1e-4 / g;
  EXPECT_NEAR(k_shallow, std::sqrt(nu) * (1.0 + nu / 6.0), 1e-9 * k_shallow);  // x tanh x = x² − x⁴/3 + …
  EXPECT_EQ(WaveField::wave_number_from_dispersion(0.0, 10.0, g), 0.0);
}

TEST(RegularWave, RampIsC1AndElevationTravelsInItsDirection) {
  const auto w = WaveField::regular(2.0, 8.0, 1.0, 2.0, deep, g);
  EXPECT_EQ(w.ramp(0.0), 0.0);
  EXPECT_EQ(w.ramp(-3.0), 0.0);
  EXPECT_NEAR(w.ramp(8.0), 0.5, 1e-15);
  EXPECT_EQ(w.ramp(16.0), 1.0);
  EXPECT_EQ(w.ramp(1e3), 1.0);
  const double h = 1e-6;  // one-sided slopes vanish at both ends (C¹), max slope π / (2 t_r) mid-way
  EXPECT_LT(w.ramp(h) / h, 1e-5);
  EXPECT_LT((1.0 - w.ramp(16.0 - h)) / h, 1e-5);
  EXPECT_NEAR((w.ramp(8.0 + h) - w.ramp(8.0 - h)) / (2 * h), pi / 32.0, 1e-8);
  for (const double x : {-50.0, 0.0, 33.0}) EXPECT_EQ(w.elevation(x, 0.0), 0.0);
  for (const double t : {16.0, 23.7, 100.0}) {
    EXPECT_NEAR(w.elevation(only(w).angular_frequency * t / only(w).wave_number, t), 1.0, 1e-12);  // crest moves +x
    EXPECT_NEAR(w.elevation(12.0, t), std::cos(only(w).wave_number * 12.0 - only(w).angular_frequency * t), 1e-15);
  }
  const auto head = WaveField::regular(2.0, 8.0, -1.0, 2.0, deep, g);
  EXPECT_NEAR(head.elevation(-only(head).angular_frequency * 30.0 / only(head).wave_number, 30.0), 1.0, 1e-12);
}

TEST(RegularWave, PressureBranches) {
  for (const double d : {deep, 30.0}) {
    const auto w = WaveField::regular(2.0, 9.0, 1.0, 0.0, d, g);
    const double k = only(w).wave_number, t = 4.1;
    const double f = std::isinf(d) ? std::exp(-12.0 * k) : std::cosh(k * (d - 12.0)) / std::cosh(k * d);
    EXPECT_NEAR(w.pressure(7.0, -12.0, t, rho), rho * g * (12.0 + w.elevation(7.0, t) * f), 1e-9);
    EXPECT_NEAR(w.depth_attenuation(only(w), -12.0), f, 1e-15);
    if (!std::isinf(d)) {
      EXPECT_NEAR(w.pressure(3.0, -d, t, rho), rho * g * (d + w.elevation(3.0, t) / std::cosh(k * d)), 1e-8);
    }
    const double x_crest = only(w).angular_frequency * t / k;  // ζ = 1: hydrostatic extension, 0 above
    EXPECT_NEAR(w.pressure(x_crest, 0.4, t, rho), rho * g * 0.6, 1e-9);
    EXPECT_EQ(w.pressure(x_crest, 1.0 + 1e-9, t, rho), 0.0);
    EXPECT_NEAR(w.pressure(x_crest, -1e-12, t, rho), w.pressure(x_crest, 0.0, t, rho), 1e-6);  // continuous at y = 0
    const double x_trough = x_crest + pi / k;  // ζ = −1: dry between the trough and y = 0
    EXPECT_EQ(w.pressure(x_trough, -0.5, t, rho), 0.0);
    EXPECT_GT(w.pressure(x_trough, -1.0 - 1e-9, t, rho), 0.0);
  }
}

TEST(RegularWave, RejectsBadInput) {
  EXPECT_THROW(WaveField::regular(-1.0, 10.0, 1.0, 2.0, deep, g), std::invalid_argument);
  EXPECT_THROW(WaveField::regular(1.0, 0.0, 1.0, 2.0, deep, g), std::invalid_argument);
  EXPECT_THROW(WaveField::regular(1.0, 10.0, 0.5, 2.0, deep, g), std::invalid_argument);
  EXPECT_THROW(WaveField::regular(1.0, 10.0, 1.0, -1.0, deep, g), std::invalid_argument);
  EXPECT_THROW(WaveField::regular(1.0, 10.0, 1.0, 2.0, 0.0, g), std::invalid_argument);
  EXPECT_THROW(WaveField::regular(1.0, 10.0, 1.0, 2.0, std::nan(""), g), std::invalid_argument);
}

// ------------------------------------------------------------------------------ calm water ----

// Global corners of the box, then the part below y = 0 (Sutherland–Hodgman on one half-plane) and
// its area and centroid by the shoelace formula.
struct AreaCentroid { double area; Vector2d centroid; };
AreaCentroid submerged_polygon(const BoxHullSection& h, double x, double y, double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  const std::array<Vector2d, 4> hull_frame = {Vector2d(h.aft_x, h.keel_y), Vector2d(h.fore_x, h.keel_y),
                                               Vector2d(h.fore_x, h.deck_y), Vector2d(h.aft_x, h.deck_y)};
  std::vector<Vector2d> box;
  for (const Vector2d& p : hull_frame) box.emplace_back(x + c * p.x() - s * p.y(), y + s * p.x() + c * p.y());
  std::vector<Vector2d> wet;
  for (std::size_t i = 0; i < box.size(); ++i) {
    const Vector2d& p = box[i];
    const Vector2d& q = box[(i + 1) % box.size()];
    if (p.y() <= 0.0) wet.push_back(p);
    if ((p.y() <= 0.0) != (q.y() <= 0.0)) wet.push_back(p + p.y() / (p.y() - q.y()) * (q - p));
  }
  double a2 = 0.0;
  Vector2d m = Vector2d::Zero();
  for (std::size_t i = 0; i < wet.size(); ++i) {
    const Vector2d& p = wet[i];
    const Vector2d& q = wet[(i + 1) % wet.size()];
    const double cross = p.x() * q.y() - q.x() * p.y();
    a2 += cross;
    m += cross * (p + q);
  }
  return {0.5 * a2, a2 != 0.0 ? Vector2d(m / (3.0 * a2)) : Vector2d(x, y)};
}

TEST(HullPressure, CalmEvenKeelBuoyancyAtTheCentreOfTheDisplacedArea) {
  for (const double draft : {0.5, 3.0, 5.5, 7.9}) {
    const double y_g1 = -hull.keel_y - draft, x_g1 = 17.0;
    const HullLoad f = load(nullptr, x_g1, y_g1, 0.0, 0.0);
    const double buoyancy = rho * g * B * L * draft;
    EXPECT_NEAR(f.force.y(), buoyancy, 1e-12 * buoyancy) << draft;
    EXPECT_NEAR(f.force.x(), 0.0, 1e-12 * buoyancy);
    EXPECT_NEAR(f.moment, buoyancy * x_f, 1e-12 * buoyancy * x_f);  // centre of buoyancy 13 m forward of G1
    EXPECT_NEAR(f.wetted_length, L + 2.0 * draft, 1e-12);
  }
}

TEST(HullPressure, ArchimedesAtTrimmedAndOvertoppedPoses) {
  struct Pose { double x, y, theta; };
  // Small trim, large trim (waterline crosses keel / deck), deck awash, nose-down, fully submerged.
  for (const Pose& p : {Pose{3.7, 1.2, 0.05}, Pose{-20.0, 0.5, 0.2}, Pose{0.0, -0.8, -0.12}, Pose{11.0, 3.0, -0.4},
                        Pose{5.0, -1.5, 0.03}, Pose{0.0, -20.0, 0.7}, Pose{-3.0, -70.0, 0.7}}) {
    const HullLoad f = load(nullptr, p.x, p.y, p.theta, 0.0);
    const AreaCentroid wet = submerged_polygon(hull, p.x, p.y, p.theta);
    const double buoyancy = rho * g * B * wet.area;
    ASSERT_GT(buoyancy, 0.0);
    EXPECT_NEAR(f.force.y(), buoyancy, 1e-10 * buoyancy) << p.theta;
    EXPECT_NEAR(f.force.x(), 0.0, 1e-10 * buoyancy);
    EXPECT_NEAR(f.moment, buoyancy * (wet.centroid.x() - p.x), 1e-10 * buoyancy * L) << p.theta;
  }
  const HullLoad full = load(nullptr, 0.0, -20.0, 0.0, 0.0);  // whole boundary wetted, deck included
  EXPECT_NEAR(full.wetted_length, 2.0 * (L + 8.0), 1e-12);
}

TEST(HullPressure, HeaveAndPitchStiffnessMatchBoxHydrostatics) {
  const double draft = 5.0, y0 = -hull.keel_y - draft, V = B * L * draft;
  const double h = 1e-3, a = 1e-5;
  const double rho_g_awp = rho * g * B * L;
  const double dfy_dy = (load(nullptr, 0, y0 + h, 0, 0).force.y() - load(nullptr, 0, y0 - h, 0, 0).force.y()) / (2 * h);
  EXPECT_NEAR(dfy_dy, -rho_g_awp, 1e-9 * rho_g_awp);
  // Symmetric box (G1 at mid-length): −dM/dθ about G1 = C55 with z_G = G1's height above keel.
  const BoxHullSection sym{-45.0, 45.0, -6.0, 2.0, 40.0};
  const Vector2d c = box_hydrostatic_stiffness(sym, rho, g, V, 6.0);
  EXPECT_NEAR(c(0), rho_g_awp, 1e-12 * rho_g_awp);
  const double c55 = rho * g * (B * L * L * L / 12.0 + V * (draft / 2.0 - 6.0));
  EXPECT_NEAR(c(1), c55, 1e-12 * c55);
  const auto moment = [&](const BoxHullSection& box, double y, double theta) { return load(nullptr, 0, y, theta, 0, box).moment; };
  EXPECT_NEAR((moment(sym, y0, a) - moment(sym, y0, -a)) / (2 * a), -c(1), 1e-6 * c(1));
  // Scene hull, G1 13 m aft of the centre of flotation: parallel axis and heave–pitch coupling.
  const double c55_g1 = box_hydrostatic_stiffness(hull, rho, g, V, 6.0)(1) + rho_g_awp * x_f * x_f;
  EXPECT_NEAR((moment(hull, y0, a) - moment(hull, y0, -a)) / (2 * a), -c55_g1, 1e-6 * c55_g1);
  EXPECT_NEAR((moment(hull, y0 + h, 0) - moment(hull, y0 - h, 0)) / (2 * h), -rho_g_awp * x_f, 1e-6 * rho_g_awp * x_f);
  const double dfy_dtheta = (load(nullptr, 0, y0, a, 0).force.y() - load(nullptr, 0, y0, -a, 0).force.y()) / (2 * a);
  EXPECT_NEAR(dfy_dtheta, -rho_g_awp * x_f, 1e-6 * rho_g_awp * x_f);
  EXPECT_THROW(box_hydrostatic_stiffness(hull, rho, g, 0.0, 6.0), std::invalid_argument);
  EXPECT_THROW(box_hydrostatic_stiffness(hull, rho, g, B * L * 8.0, 6.0), std::invalid_argument);
}

// ------------------------------------------------------------------------ Froude–Krylov ----

// Vertical profile f(y) and its antiderivatives F0 = ∫f dy, F1 = ∫f (y − Y) dy.
struct Profile {
  double k, d;
  double f(double y) const { return std::isinf(d) ? std::exp(k * y) : std::cosh(k * (y + d)) / std::cosh(k * d); }
  double F0(double y) const { return std::isinf(d) ? std::exp(k * y) / k : std::sinh(k * (y + d)) / (k * std::cosh(k * d)); }
  double F1(double y, double Y) const {
    if (std::isinf(d)) return std::exp(k * y) * ((y - Y) / k - 1.0 / (k * k));
    return ((y - Y) * std::sinh(k * (y + d)) / k - std::cosh(k * (y + d)) / (k * k)) / std::cosh(k * d);
  }
};

TEST(HullPressure, FroudeKrylovOnASubmergedBoxMatchesClosedForm) {
  // Scene wave (λ = 156 m) deep and at 60 m depth; a short wave (λ = 39 m, kL = 14) checks that
  // the quadrature resolves several wavelengths along the keel.
  for (const auto& [d, period, Y] : {std::tuple{deep, 10.0, -30.0}, {60.0, 10.0, -30.0}, {deep, 5.0, -10.0}, {40.0, 5.0, -10.0}}) {
    const auto w = WaveField::regular(1.0, period, 1.0, 2.0, d, g);
    const Profile pr{only(w).wave_number, d};
    const double k = only(w).wave_number, za = only(w).amplitude;
    for (const double t : {25.0, 31.3, 47.9}) {
      const double X = 11.0, yb = Y + hull.keel_y, yt = Y + hull.deck_y;
      const double xi1 = hull.aft_x, xi2 = hull.fore_x, H = yt - yb;
      const auto phase = [&](double xi) { return k * (X + xi) - only(w).angular_frequency * t; };
      const double S0 = (std::sin(phase(xi2)) - std::sin(phase(xi1))) / k;  // ∫ cos φ dξ
      const auto s1 = [&](double xi) { return xi * std::sin(phase(xi)) / k + std::cos(phase(xi)) / (k * k); };
      const double S1 = s1(xi2) - s1(xi1);  // ∫ ξ cos φ dξ
      const double fy_dyn = rho * g * B * za * (pr.f(yb) - pr.f(yt)) * S0;
      const double fx_dyn = rho * g * B * za * (std::cos(phase(xi1)) - std::cos(phase(xi2))) * (pr.F0(yt) - pr.F0(yb));
      const double m_dyn = rho * g * B * za * ((pr.f(yb) - pr.f(yt)) * S1 +
                                               (std::cos(phase(xi2)) - std::cos(phase(xi1))) * (pr.F1(yt, Y) - pr.F1(yb, Y)));
      const double fy_static = rho * g * B * L * H, m_static = fy_static * x_f;
      const HullLoad f = load(&w, X, Y, 0.0, t);
      const double scale = rho * g * B * za * std::exp(k * yt) * L;  // dynamic force scale
      EXPECT_NEAR(f.force.y() - fy_static, fy_dyn, 1e-10 * scale) << "d = " << d << ", T = " << period << ", t = " << t;
      EXPECT_NEAR(f.force.x(), fx_dyn, 1e-10 * scale);
      EXPECT_NEAR(f.moment - m_static, m_dyn, 1e-10 * scale * L);
      EXPECT_GT(std::abs(fy_dyn), 1e-3 * scale);  // the wave term is really there
    }
  }
}

// Floating box at even keel in a deep-water wave whose crest overtops the deck (deck at y_d ≥ 0).
// Faces and bottom: p = ρg(−y + ζ e^{ky}) below 0, ρg(ζ − y) from 0 to the crest; deck wetted
// where ζ > y_d with p = ρg(ζ − y_d). Returns (F_x, F_y, M about G1, wetted length).
Eigen::Vector4d overtopped_closed_form(const WaveField& w, double X, double Y, double t) {
  const double k = only(w).wave_number, za = only(w).amplitude, wt = only(w).angular_frequency * t, rg = rho * g;
  const double yb = Y + hull.keel_y, yd = Y + hull.deck_y, x1 = X + hull.aft_x, x2 = X + hull.fore_x;
  const auto zeta = [&](double x) { return za * std::cos(k * x - wt); };
  const auto face = [&](double x) {  // (∫p dy, ∫p (y − Y) dy, wetted height) on a vertical face at x
    const double z = zeta(x), top = std::min(z, yd), y_airy = std::min(top, 0.0);
    const auto a0 = [&](double y) { return -y * y / 2 + z * std::exp(k * y) / k; };
    const auto a1 = [&](double y) { return -y * y * y / 3 + Y * y * y / 2 + z * std::exp(k * y) * ((y - Y) / k - 1 / (k * k)); };
    const auto e0 = [&](double y) { return z * y - y * y / 2; };
    const auto e1 = [&](double y) { return z * y * y / 2 - z * Y * y - y * y * y / 3 + Y * y * y / 2; };
    Eigen::Vector3d r(rg * (a0(y_airy) - a0(yb)), rg * (a1(y_airy) - a1(yb)), top - yb);
    if (top > 0.0) r += Eigen::Vector3d(rg * (e0(top) - e0(0.0)), rg * (e1(top) - e1(0.0)), 0.0);
    return r;
  };
  const auto cos_int = [&](double u, double v) { return (std::sin(k * v - wt) - std::sin(k * u - wt)) / k; };
  const auto xcos = [&](double x) { return (x - X) * std::sin(k * x - wt) / k + std::cos(k * x - wt) / (k * k); };
  const Eigen::Vector3d stern = face(x1), bow = face(x2);
  double fx = B * (stern(0) - bow(0)), m = B * (bow(1) - stern(1));
  double fy = B * rg * (-yb * L + za * std::exp(k * yb) * cos_int(x1, x2));  // bottom, wholly wet
  m += B * rg * (-yb * ((x2 - X) * (x2 - X) - (x1 - X) * (x1 - X)) / 2 + za * std::exp(k * yb) * (xcos(x2) - xcos(x1)));
  double wetted = L + stern(2) + bow(2);
  if (yd < za) {  // deck: cos(kx − ωt) > y_d / ζ_a on intervals of half-width α / k around each crest
    const double alpha = std::acos(yd / za);
    for (int n = static_cast<int>(std::floor((k * x1 - wt) / (2 * pi))) - 1; n <= static_cast<int>(std::ceil((k * x2 - wt) / (2 * pi))) + 1; ++n) {
      const double u = std::max(x1, (2 * pi * n - alpha + wt) / k), v = std::min(x2, (2 * pi * n + alpha + wt) / k);
      if (!(v > u)) continue;
      fy -= B * rg * (za * cos_int(u, v) - yd * (v - u));
      m -= B * rg * (za * (xcos(v) - xcos(u)) - yd * ((v - X) * (v - X) - (u - X) * (u - X)) / 2);
      wetted += v - u;
    }
  }
  return {fx, fy, m, wetted};
}

TEST(HullPressure, OvertoppedDeckAndWaveClippedFacesMatchClosedForm) {
  int overtopped = 0;
  // Scene wave and a shorter one (λ = 56 m: several crossings per edge, two crests on deck).
  for (const auto& [period, offset] : {std::pair{10.0, -20.0}, {10.0, 40.0}, {10.0, 70.0}, {10.0, 110.0}, {10.0, -60.0},
                                       {6.0, 0.0}, {6.0, 17.0}, {6.0, 33.0}, {6.0, -41.0}}) {
    const auto w = WaveField::regular(2.0, period, 1.0, 2.0, deep, g);
    const double t = 30.0, Y = -1.7;  // deck 0.3 m above still water, crest 1 m
    const double X = only(w).angular_frequency * t / only(w).wave_number - offset;  // crest `offset` forward of G1
    const Eigen::Vector4d ref = overtopped_closed_form(w, X, Y, t);
    const HullLoad f = load(&w, X, Y, 0.0, t);
    const double scale = rho * g * B * L * 7.7;
    EXPECT_NEAR(f.force.x(), ref(0), 1e-10 * scale) << offset;
    EXPECT_NEAR(f.force.y(), ref(1), 1e-10 * scale) << offset;
    EXPECT_NEAR(f.moment, ref(2), 1e-10 * scale * L) << offset;
    EXPECT_NEAR(f.wetted_length, ref(3), 1e-10 * L) << offset;
    overtopped += ref(3) > L + 2 * 7.7 + 1.0;
  }
  EXPECT_GE(overtopped, 2);  // the deck really took water in some of the cases
}

TEST(HullPressure, LongWaveHeaveForceIsQuasiStatic) {
  const auto w = WaveField::regular(1.0, 200.0, 1.0, 0.0, deep, g);  // λ ≈ 62 km
  ASSERT_GT(wavelength(w), 6e4);
  const double draft = 5.0, X = 100.0, Y = -hull.keel_y - draft, k = only(w).wave_number;
  const HullLoad calm = load(nullptr, X, Y, 0.0, 0.0);
  for (const double t : {0.0, 13.0, 50.0, 77.0, 140.0}) {
    const HullLoad f = load(&w, X, Y, 0.0, t);
    const double zeta_mid = w.elevation(X + x_f, t);
    EXPECT_NEAR(f.force.y() - calm.force.y(), rho * g * B * L * zeta_mid, 1e-3 * rho * g * B * L * only(w).amplitude) << t;
    const auto xcos = [&](double xi) { return xi * std::sin(k * (X + xi) - only(w).angular_frequency * t) / k +
                                              std::cos(k * (X + xi) - only(w).angular_frequency * t) / (k * k); };
    const double m_qs = rho * g * B * only(w).amplitude * (xcos(hull.fore_x) - xcos(hull.aft_x));  // ρgB ∫ζ ξ dξ
    EXPECT_NEAR(f.moment - calm.moment, m_qs, 1e-3 * rho * g * B * only(w).amplitude * L * L / 2) << t;
  }
}

TEST(HullPressure, RampedWaveStartsFromCalmWater) {
  const auto w = WaveField::regular(1.0, 10.0, 1.0, 2.0, deep, g);
  const HullLoad calm = load(nullptr, 4.0, 1.0, 0.02, 0.0), start = load(&w, 4.0, 1.0, 0.02, 0.0);
  EXPECT_NEAR(start.force.y(), calm.force.y(), 1e-12 * calm.force.y());
  EXPECT_NEAR(start.force.x(), calm.force.x(), 1e-12 * calm.force.y());
  EXPECT_NEAR(start.moment, calm.moment, 1e-12 * calm.force.y() * L);
}

// ------------------------------------------------------------------- robustness, hot path ----

TEST(HullPressure, DryHullNonFinitePoseAndInconsistentGravity) {
  const auto w = WaveField::regular(1.0, 10.0, 1.0, 2.0, deep, g);
  for (const WaveField* wave : {static_cast<const WaveField*>(nullptr), &w}) {
    const HullLoad dry = load(wave, 0.0, 50.0, 0.3, 40.0);
    EXPECT_TRUE(dry.force.isZero(0.0));
    EXPECT_EQ(dry.moment, 0.0);
    EXPECT_EQ(dry.wetted_length, 0.0);
  }
  const double nan = std::nan("");
  try {
    load(&w, 1.0, nan, 0.0, 3.0);
    FAIL() << "no throw";
  } catch (const std::domain_error& e) {
    EXPECT_NE(std::string(e.what()).find("nan"), std::string::npos) << e.what();
  }
  EXPECT_THROW(load(nullptr, 0.0, 0.0, deep, 0.0), std::domain_error);
  const auto other = WaveField::regular(1.0, 10.0, 1.0, 2.0, deep, 9.80665);
  EXPECT_THROW(load(&other, 0.0, 0.0, 0.0, 30.0), std::invalid_argument);
  EXPECT_THROW(load(nullptr, 0.0, 0.0, 0.0, 0.0, BoxHullSection{1.0, -1.0, -6.0, 2.0, 40.0}), std::invalid_argument);
}

TEST(HullPressure, AllocatesNothing) {
  const auto w = WaveField::regular(2.0, 10.0, 1.0, 2.0, deep, g);
  double sink = 0.0;
  allocation_count = 0;
  counting_allocations = true;
  for (int i = 0; i < 200; ++i) {
    const HullLoad f = hull_pressure_load(hull, i % 2 ? &w : nullptr, rho, g, Vector2d(0.1 * i, -1.7), 0.001 * i, 0.3 * i);
    sink += f.force.y() + f.moment;
  }
  counting_allocations = false;
  EXPECT_EQ(allocation_count, 0);
  EXPECT_TRUE(std::isfinite(sink));
}

}  // namespace hydro_test
