// Self-checks of the A-frame crane reference (a_frame_reference.hpp): its rest statics against hand
// moment balances, its rigid model's analytic derivatives against finite differences of its
// potential, its elastic model against the fixed-anchor pinned-boom reference (A-frame held), the
// rigid model (boom stiff) and hand formulas (the A-frame's own mode, a simply supported sag).
#include "a_frame_reference.hpp"
#include "pinned_boom_reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace ffrf::test::a_frame_reference_checks {

double relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

double worst_relative(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  double worst = 0.0;
  for (Eigen::Index i = 0; i < b.size(); ++i) worst = std::max(worst, relative(a(i), b(i)));
  return worst;
}

// Distance from point c to the line through a and b (twice the triangle's area over the base).
double lever(const Eigen::Vector2d& c, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d u = b - a, w = c - a;
  return std::abs(u.x() * w.y() - u.y() * w.x()) / u.norm();
}

// A vertical A-frame P = (0, 0), T = (0, h), a horizontal backstay to D = (−20, h), a horizontal
// boom from B = (10, 0) to the tip (10 + L, 0), G_A on the A-frame's axis.
AFrameCrane textbook_crane(double h) {
  AFrameCrane p;
  p.heel = {10.0, 0.0};
  p.boom_length = 100.0;
  p.boom_angle = 0.0;
  p.pivot = {0.0, 0.0};
  p.top = {0.0, h};
  p.a_frame_cg = {0.0, 0.5 * h};
  p.deck_point = {-20.0, h};
  p.tip_mass = 5.0e4;
  return p;
}

// A vertical A-frame P = (100, 0), T = (100, 50) straight above the tip of a horizontal boom from
// B = (0, 10): the luffing wire is vertical (⊥ boom, ⊥ T's motion), the backstay horizontal to
// D = (50, 50), G_A offset 5 m forward so that the backstay carries the A-frame's weight moment.
AFrameCrane decoupled_crane() {
  AFrameCrane p;
  p.heel = {0.0, 10.0};
  p.boom_length = 100.0;
  p.boom_angle = 0.0;
  p.pivot = {100.0, 0.0};
  p.top = {100.0, 50.0};
  p.a_frame_cg = {105.0, 25.0};
  p.deck_point = {50.0, 50.0};
  p.backstay_count = 1;
  p.backstay_stiffness = 1.0e6;
  return p;
}

// The boom s = 1e5 times stiffer, on N = 4 elements: its elastic modes' share in the lowest two
// falls as 1/s (1e-5 of the rigid frequencies at s = 1e4), while the eigensolver's absolute
// round-off ε λ_max grows as s N² (1e-4 relative at s = 1e6, N = 16 on the softest case); here
// both stay ~1e-6.
constexpr int stiff_elements = 4;
AFrameCrane stiff_boom(AFrameCrane p) {
  p.EI *= 1e5;
  p.EA *= 1e5;
  return p;
}

TEST(AFrameReference, RestTensionsOfTheTextbookCrane) {
  const double h = 30.0, g = 9.81;
  const AFrameCrane p = textbook_crane(h);
  const AFrameRest r = rest_tensions(p);
  // Boom: the wire's vertical part T_L sin θ at the tip balances W/2 + m_tip g (moments about B).
  // A-frame: only the wire's horizontal part T_L cos θ has a lever (h) about P, the backstay's h.
  const double run = 10.0 + p.boom_length, l = std::hypot(run, h);
  const double W = p.mass_per_length * p.boom_length * g;
  const double TL = (0.5 * W + p.tip_mass * g) / (h / l), TB = TL * run / l;
  std::printf("[ measured ] textbook T_L = %.6e N (hand %.6e), T_B = %.6e N (hand %.6e)\n",
              r.luffing_tension, TL, r.backstay_tension, TB);
  EXPECT_LT(relative(r.luffing_tension, TL), 1e-13);
  EXPECT_LT(relative(r.backstay_tension, TB), 1e-13);
  EXPECT_LT(relative(r.luffing_length, l), 1e-15);
  EXPECT_LT(relative(r.backstay_length, 20.0), 1e-15);
  EXPECT_NEAR(r.luffing_unstretched, l - TL / (2.0 * 1e8), 1e-12);
  EXPECT_NEAR(r.backstay_unstretched, 20.0 - TB / (2.0 * 1e8), 1e-12);
}

TEST(AFrameReference, RestTensionsOfTheDefaultsByLeverArms) {
  const AFrameCrane p;
  const AFrameRest r = rest_tensions(p);
  const double g = 9.81, L = p.boom_length, c = std::cos(p.boom_angle);
  const Eigen::Vector2d tip = p.heel + L * Eigen::Vector2d(c, std::sin(p.boom_angle));
  // Moment arms: the weights' horizontal offsets, the wires' perpendicular distances; G_A is
  // straight above P by default, so the backstay balances the luffing pull alone.
  const double TL = (p.mass_per_length * L * g * 0.5 * L * c) / lever(p.heel, tip, p.top);
  const double TB = TL * lever(p.pivot, tip, p.top) / lever(p.pivot, p.top, p.deck_point);
  std::printf("[ measured ] defaults: T_L = %.9e N, T_B = %.9e N, L0_L = %.9f m, L0_B = %.9f m\n",
              r.luffing_tension, r.backstay_tension, r.luffing_unstretched, r.backstay_unstretched);
  EXPECT_LT(relative(r.luffing_tension, TL), 1e-13);
  EXPECT_LT(relative(r.backstay_tension, TB), 1e-13);
}

TEST(AFrameReference, SlackWiresAreRefused) {
  AFrameCrane p = decoupled_crane();
  p.a_frame_cg = {100.0, 25.0};  // no moment left for the backstay: T_B = 0
  EXPECT_THROW(rest_tensions(p), std::invalid_argument);
  p = AFrameCrane{};
  p.deck_point = {30.0, 8.0};  // backstay forward of the A-frame: it would have to push
  EXPECT_THROW(rest_tensions(p), std::invalid_argument);
  p = AFrameCrane{};
  p.gravity = 0.0;  // nothing to hold
  EXPECT_THROW(rest_tensions(p), std::invalid_argument);
}

TEST(AFrameReference, RigidEquilibriumIsTheRestStateWithTheDerivedLengths) {
  for (const AFrameCrane& p : {AFrameCrane{}, textbook_crane(30.0), decoupled_crane()}) {
    const Eigen::Vector2d q = rigid_static_equilibrium(p);
    std::printf("[ measured ] equilibrium (beta, psi) = (%.3e, %.3e)\n", q(0), q(1));
    EXPECT_LT(q.lpNorm<Eigen::Infinity>(), 1e-14);
  }
}

// Central differences of rigid_potential, steps h: the gradient's error ~ h²V'''/6 with V''' ~ kL²
// (angles of order 1 change the geometry by its own size), 1e-10 relative; the Hessian's ~
// h²V''''/12 and round-off ε|V|/h² (|V| ~ 1e9 J with the heights, H ~ 1e12), both ~ 1e-9.
TEST(AFrameReference, RigidAnalyticDerivativesMatchFiniteDifferences) {
  AFrameCrane p;
  p.tip_mass = 3.0e4;
  p = with_rest_lengths(p);
  const double hg = 1e-5, hh = 1e-4;
  for (const Eigen::Vector2d& q : {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(0.02, -0.01),
                                  Eigen::Vector2d(-0.05, 0.03)}) {
    const RigidEnergy a = rigid_energy(p, q(0), q(1));
    auto V = [&](double db, double dp) { return rigid_potential(p, q(0) + db, q(1) + dp); };
    const Eigen::Vector2d grad((V(hg, 0) - V(-hg, 0)) / (2 * hg),
                               (V(0, hg) - V(0, -hg)) / (2 * hg));
    Eigen::Matrix2d H;
    H(0, 0) = (V(hh, 0) - 2 * V(0, 0) + V(-hh, 0)) / (hh * hh);
    H(1, 1) = (V(0, hh) - 2 * V(0, 0) + V(0, -hh)) / (hh * hh);
    H(0, 1) = H(1, 0) = (V(hh, hh) - V(hh, -hh) - V(-hh, hh) + V(-hh, -hh)) / (4 * hh * hh);
    const double grad_error = (grad - a.gradient).norm() / (a.hessian.norm() * 0.05);
    const double hess_error = (H - a.hessian).norm() / a.hessian.norm();
    std::printf("[ measured ] (%.2f, %.2f): gradient error %.2e, Hessian error %.2e\n", q(0), q(1),
                grad_error, hess_error);
    EXPECT_LT(grad_error, 1e-8);
    EXPECT_LT(hess_error, 1e-7);
  }
}

// Loaded beyond its rest design (a tip mass added after the lengths are fixed), the boom sinks to
// a new equilibrium where the finite-difference gradient of V vanishes.
TEST(AFrameReference, RigidNewtonFindsALoadedEquilibrium) {
  AFrameCrane p = with_rest_lengths(AFrameCrane{});
  p.tip_mass = 5.0e5;
  const Eigen::Vector2d q = rigid_static_equilibrium(p);
  // Fourth-order central differences (truncation h⁴V⁽⁵⁾/30, round-off ~ ε|V|/h).
  const double h = 1e-4;
  auto d = [&](const Eigen::Vector2d& dir) {
    auto V = [&](double s) { return rigid_potential(p, q(0) + s * dir(0), q(1) + s * dir(1)); };
    return (V(-2 * h) - 8 * V(-h) + 8 * V(h) - V(2 * h)) / (12 * h);
  };
  const double dVb = d(Eigen::Vector2d(1, 0)), dVp = d(Eigen::Vector2d(0, 1));
  const double scale = p.tip_mass * p.gravity * p.boom_length;  // the added moment
  std::printf("[ measured ] tip mass 500 t: beta = %.6e, psi = %.6e, |grad V| / m g L = %.2e\n",
              q(0), q(1), std::hypot(dVb, dVp) / scale);
  EXPECT_LT(q(0), 0.0);
  EXPECT_LT(q(1), 0.0);  // the luffing wires pull the A-frame forward (clockwise)
  EXPECT_LT(std::hypot(dVb, dVp) / scale, 1e-8);
}

// A horizontal boom: gravity is transverse, so N(x) = T_L (u_L · e) is uniform, and with the
// A-frame held (I_A → ∞) or its backstay rigid the boom is the fixed-anchor pinned boom.
PinnedBoom pinned_equivalent(const AFrameCrane& p) {
  const AFrameRest r = rest_tensions(p);
  PinnedBoom b;
  b.length = p.boom_length;
  b.EI = p.EI;
  b.EA = p.EA;
  b.mass_per_length = p.mass_per_length;
  b.wire_stiffness = p.luffing_count * p.luffing_stiffness;
  b.wire_direction_local = r.luffing_direction;  // α = 0: boom frame = global
  b.tip_mass = p.tip_mass;
  b.wire_tension = r.luffing_tension;
  b.wire_length = r.luffing_length;
  b.axial_force_uniform = r.luffing_tension * r.luffing_direction.x();
  return b;
}

TEST(AFrameReference, HeldAFrameGivesThePinnedBoomReference) {
  AFrameCrane p;
  p.boom_angle = 0.0;
  p.tip_mass = 3.0e4;
  const PinnedBoom b = pinned_equivalent(p);
  const int N = 16, count = 8;
  const Eigen::VectorXd pinned = natural_frequencies_fe(b, N, count);

  AFrameCrane held = p;
  held.a_frame_inertia = 1e30;  // ψ frozen: its mode goes to ω ≈ 0, the others are ψ = 0's
  const Eigen::VectorXd omega = elastic_frequencies(held, N, count + 1);
  EXPECT_LT(omega(0), 1e-6);
  const double held_error = worst_relative(omega.tail(count), pinned);

  AFrameCrane stiff = p;
  stiff.backstay_stiffness = 1e15;  // ψ held statically, to O(n_L k_L / (n_B k_B)) = 1e-7
  const double stiff_error = worst_relative(elastic_frequencies(stiff, N, count), pinned);
  std::printf("[ measured ] vs pinned boom: I_A = 1e30 %.2e, k_B = 1e15 %.2e (f1 = %.6f Hz)\n",
              held_error, stiff_error, pinned(0) / (2 * std::numbers::pi));
  EXPECT_LT(held_error, 1e-10);
  EXPECT_LT(stiff_error, 1e-6);

  // Statics: the same loads (weight, tip weight, the rest pull T_L u_L at the tip).
  const Eigen::Vector2d g_local(0.0, -p.gravity);
  const PinnedBoomStatic ref =
      static_deflection_fe(b, N, g_local, b.wire_tension * b.wire_direction_local);
  const AFrameStatic s = elastic_static_deflection(stiff, N);
  const double static_error =
      (s.nodal - ref.nodal).lpNorm<Eigen::Infinity>() / ref.nodal.lpNorm<Eigen::Infinity>();
  std::printf("[ measured ] statics vs pinned boom: %.2e (tip v = %.6e m, psi = %.2e)\n",
              static_error, s.tip_displacement(1), s.a_frame_rotation);
  EXPECT_LT(static_error, 1e-5);
  EXPECT_NEAR(s.luffing_tension_change, ref.wire_force, 1e-5 * b.wire_tension);
}

// The boom stiff (stiff_boom): the lowest two modes are the rigid model's, including the load
// terms, which the elastic model carries in N(x) (the boom) and in K_ψψ (the A-frame). Softer
// wires make the load terms ~10 % of the stiffness.
TEST(AFrameReference, StiffBoomGivesTheRigidModel) {
  AFrameCrane soft;
  soft.luffing_stiffness = soft.backstay_stiffness = 2.0e6;
  AFrameCrane loaded;
  loaded.tip_mass = 2.0e5;
  for (const AFrameCrane& p : {AFrameCrane{}, soft, loaded}) {
    const Eigen::Vector2d rigid = rigid_frequencies(p);
    const Eigen::VectorXd elastic = elastic_frequencies(stiff_boom(p), stiff_elements, 2);
    const double error = worst_relative(elastic, rigid);
    std::printf("[ measured ] rigid %.9f, %.9f Hz; stiff elastic deviates %.2e\n",
                rigid(0) / (2 * std::numbers::pi), rigid(1) / (2 * std::numbers::pi), error);
    EXPECT_LT(error, 1e-5);
  }
}

// The decoupled crane: the luffing wire is vertical, so T's motion ψ Ĩ(T − P) = ψ (−r, 0) is
// along the backstay and across the luffing wire, and the tip's motion (vertical) is along the
// luffing wire and across T's: the A-frame's mode is alone. By hand, K_ψψ = r²(n_B k_B + T_L/ℓ_L)
// (backstay stretched, luffing wire swung) − r T_L (the downward pull at T, a point that drops by
// ½ψ²r) − 25 m m_A g (G_A 25 m up drops likewise), I_P = I_A + m_A(5² + 25²). The boom's own:
// K_ββ = L² n_L k_L (no load terms: all forces on the horizontal boom are vertical), I_B = ρA L³/3.
TEST(AFrameReference, AFrameModeByHand) {
  const AFrameCrane p = decoupled_crane();
  const double g = 9.81, r = 50.0, lL = 40.0, L = p.boom_length;
  const double TL = 0.5 * p.mass_per_length * L * g;
  const double K_psi =
      r * r * (p.backstay_stiffness + TL / lL) - r * TL - 25.0 * p.a_frame_mass * g;
  const double I_P = p.a_frame_inertia + p.a_frame_mass * (25.0 + 625.0);
  const double K_beta = L * L * p.luffing_count * p.luffing_stiffness;
  const double I_B = p.mass_per_length * L * L * L / 3.0;
  const double hand_psi = std::sqrt(K_psi / I_P), hand_beta = std::sqrt(K_beta / I_B);
  ASSERT_LT(hand_psi, hand_beta);  // the A-frame's mode first here

  const Eigen::Vector2d rigid = rigid_frequencies(p);
  const Eigen::VectorXd elastic = elastic_frequencies(stiff_boom(p), stiff_elements, 2);
  std::printf("[ measured ] A-frame mode: hand %.9f rad/s (load terms %.1f %%), rigid %.2e, "
              "stiff elastic %.2e; boom mode: rigid %.2e, stiff elastic %.2e\n", hand_psi,
              100.0 * (r * TL + 25.0 * p.a_frame_mass * g) / K_psi, relative(rigid(0), hand_psi),
              relative(elastic(0), hand_psi), relative(rigid(1), hand_beta),
              relative(elastic(1), hand_beta));
  EXPECT_LT(relative(rigid(0), hand_psi), 1e-12);
  EXPECT_LT(relative(rigid(1), hand_beta), 1e-12);
  EXPECT_LT(relative(elastic(0), hand_psi), 1e-9);  // decoupled from the boom's bending
  EXPECT_LT(relative(elastic(1), hand_beta), 3e-5);  // the boom's flexibility, O(1/s)
}

// The decoupled crane's boom under its own weight: the rest pull T_L = qL/2 at the tip already
// balances the weight's moment and gravity has no axial part, so the wire does not stretch, ψ and
// u stay 0 and the boom sags as a simply supported beam, 5qL⁴/(384 EI) at mid-span (nodally exact
// for cubic Hermite elements under a uniform load).
TEST(AFrameReference, SagOfTheDecoupledBoomIsSimplySupported) {
  const AFrameCrane p = decoupled_crane();
  const int N = 16;
  const AFrameStatic s = elastic_static_deflection(p, N);
  const double q = p.mass_per_length * p.gravity, L = p.boom_length;
  const double hand = -5.0 * q * L * L * L * L / (384.0 * p.EI);
  std::printf("[ measured ] mid-span sag %.9e m (hand %.9e), tip (%.1e, %.1e), psi %.1e\n",
              s.nodal(3 * (N / 2) + 1), hand, s.tip_displacement(0), s.tip_displacement(1),
              s.a_frame_rotation);
  EXPECT_LT(relative(s.nodal(3 * (N / 2) + 1), hand), 1e-10);
  EXPECT_LT(s.tip_displacement.norm(), 1e-12 * std::abs(hand));
  EXPECT_LT(std::abs(s.a_frame_rotation), 1e-14);
  const double heel_slope = -q * L * L * L / (24.0 * p.EI);
  EXPECT_NEAR(s.nodal(2), heel_slope, 1e-10 * std::abs(heel_slope));
}

// The loads f do no work on the boom's rigid rotation (v = x, φ = 1) nor on ψ: the rest tensions
// balance the moments about B and P.
TEST(AFrameReference, LoadsAreBalancedOnTheRigidMotions) {
  AFrameCrane p;
  p.tip_mass = 1.0e5;
  const int N = 8;
  const AFrameElastic s = assemble_a_frame_crane(p, N);
  Eigen::VectorXd rigid = Eigen::VectorXd::Zero(s.K.rows());
  rigid(0) = 1.0;  // heel φ
  for (int i = 1; i <= N; ++i) {
    rigid(3 * i - 1) = i * p.boom_length / N;  // v_i (free index 3i − 1)
    rigid(3 * i) = 1.0;                        // φ_i
  }
  const double moment_scale = p.mass_per_length * p.boom_length * p.gravity * p.boom_length;
  EXPECT_LT(std::abs(s.f.dot(rigid)) / moment_scale, 1e-14);
  EXPECT_LT(std::abs(s.f(s.psi_index())) / moment_scale, 1e-14);
  EXPECT_LT((s.K - s.K.transpose()).norm(), 1e-14 * s.K.norm());
}

}  // namespace ffrf::test::a_frame_reference_checks
