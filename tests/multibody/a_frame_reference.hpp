// Independent reference of a planar crane on a held deck: a boom pinned at its heel B, luffed by
// n_L wires from its tip to the top T of an A-frame; the A-frame a rigid body pinned on the deck at
// its pivot P and held by n_B backstays from T to a deck point D; an optional point mass at the
// tip.
// The second method the crane's code is checked against: only Eigen (its solvers compiled once in
// linalg/) and the standard library are used — nothing of fem/, modal/ or multibody/ — and every formula is derived here from its
// definition (energy, virtual work). Planar, SI, global = deck frame, x forward, y up, angles
// counter-clockwise, gravity −y. Ĩ is the 90° rotation, Ĩ(x, y) = (−y, x); the planar cross
// product a × b = a_x b_y − a_y b_x.
// 1. Rest statics of the rigid boom (moments about B and P) and the unstretched wire lengths that
//    make the rest state an equilibrium.
// 2. A rigid boom: two coordinates (β, ψ), the boom's rotation about B from α and the A-frame's
//    about P from rest, with the EXACT nonlinear potential, its analytic gradient and Hessian,
//    Newton for the equilibrium and the two frequencies.
// 3. An elastic boom, linearised about the rest state with gravity: bar + cubic Hermite beam
//    elements (e.g. Cook, Malkus, Plesha & Witt, "Concepts and Applications of FEA"), consistent
//    mass, the geometric stiffness of the boom's axial force N(x) and of the wires' tensions, and
//    the A-frame's load stiffness; its frequencies and its linear static deflection.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

// Eigen's own dense eigen solvers, compiled once for the project (the same Eigen code, declared extern).
#include "linalg/dense_solvers.hpp"

namespace ffrf::test {

// Defaults: roughly the project's shipped crane. The A-frame's centre of mass and rotary inertia
// are stored as values (the midpoint of P and T and m_A|T − P|²/12 of the default geometry): they
// do not follow a change of P or T.
struct AFrameCrane {
  Eigen::Vector2d heel{35.0, 8.0};             // B, m
  double boom_length = 120.0;                  // L, m
  double boom_angle = std::numbers::pi / 3.0;  // α above horizontal at rest, rad
  double EI = 2.1e11 * 11.4;                   // N m²
  double EA = 2.1e11 * 1.27;                   // N
  double mass_per_length = 1.0e4;              // ρA, kg/m
  int luffing_count = 2;                       // n_L
  double luffing_stiffness = 1.0e8;            // k_L of each wire, N/m
  double luffing_unstretched = -1.0;           // L0_L of each, m; negative: that of rest_tensions
  Eigen::Vector2d pivot{0.0, 8.0};             // P
  Eigen::Vector2d top{0.0, 40.0};              // T at rest
  Eigen::Vector2d a_frame_cg{0.0, 24.0};       // G_A at rest
  double a_frame_mass = 100.0e3;               // m_A, kg
  double a_frame_inertia = 100.0e3 * 32.0 * 32.0 / 12.0;  // I_A about G_A, kg m²
  Eigen::Vector2d deck_point{-30.0, 8.0};      // D
  int backstay_count = 2;                      // n_B
  double backstay_stiffness = 1.0e8;           // k_B of each, N/m
  double backstay_unstretched = -1.0;          // L0_B of each, m; negative: that of rest_tensions
  double tip_mass = 0.0;                       // m_tip, kg (no rotary inertia)
  double gravity = 9.81;                       // g, m/s²
};

namespace a_frame_detail {
inline Eigen::Vector2d perp(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }
inline double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}
inline Eigen::Vector2d rotate(const Eigen::Vector2d& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}
inline void validate(const AFrameCrane& p) {
  if (!(p.boom_length > 0.0) || !(p.mass_per_length > 0.0) || !(p.EI > 0.0) || !(p.EA > 0.0) ||
      p.luffing_count < 1 || p.backstay_count < 1 || !(p.luffing_stiffness > 0.0) ||
      !(p.backstay_stiffness > 0.0) || !(p.a_frame_mass >= 0.0) || !(p.a_frame_inertia >= 0.0) ||
      !(p.tip_mass >= 0.0) || !(p.gravity >= 0.0) ||
      !(p.a_frame_inertia + p.a_frame_mass * (p.a_frame_cg - p.pivot).squaredNorm() > 0.0)) {
    throw std::invalid_argument("a-frame crane: positive L, rhoA, EI, EA, wire counts and "
                                "stiffnesses and A-frame inertia about P; non-negative masses, g");
  }
}
}  // namespace a_frame_detail

inline Eigen::Vector2d boom_axis(const AFrameCrane& p) {
  return {std::cos(p.boom_angle), std::sin(p.boom_angle)};
}
inline Eigen::Vector2d boom_tip(const AFrameCrane& p) {
  return p.heel + p.boom_length * boom_axis(p);
}
// Rotary inertias about the pins: I_B = ∫ρA x² dx + m_tip L², I_P = I_A + m_A |G_A − P|² (Steiner).
inline double boom_pivot_inertia(const AFrameCrane& p) {
  const double L = p.boom_length;
  return p.mass_per_length * L * L * L / 3.0 + p.tip_mass * L * L;
}
inline double a_frame_pivot_inertia(const AFrameCrane& p) {
  return p.a_frame_inertia + p.a_frame_mass * (p.a_frame_cg - p.pivot).squaredNorm();
}

// ---------------------------------------------------------------- 1. rest statics
struct AFrameRest {
  double luffing_tension = 0.0, backstay_tension = 0.0;  // totals over the n wires, N
  double luffing_length = 0.0, backstay_length = 0.0;    // ℓ at rest, m
  double luffing_unstretched = 0.0, backstay_unstretched = 0.0;  // L0 of each wire, m
  Eigen::Vector2d luffing_direction, backstay_direction;  // unit, tip → T and T → D
};

// Boom (rigid, at α): moments about B of its weight ρA L g at mid-length, the tip mass's weight
// and the luffing pull T_L u_L at the tip (u_L unit tip → T) vanish:
//   (L/2 e) × (0, −ρA L g) + (L e) × (0, −m_tip g) + T_L (L e) × u_L = 0.
// A-frame (at rest): moments about P of the luffing pull on T (−T_L u_L, towards the tip), the
// backstay pull T_B u_B (u_B unit T → D) and its weight at G_A vanish:
//   (T − P) × (−T_L u_L) + T_B (T − P) × u_B + (G_A − P) × (0, −m_A g) = 0.
// Each wire carries T/n; Hooke T/n = k(ℓ − L0) gives L0 = ℓ − T/(n k).
inline AFrameRest rest_tensions(const AFrameCrane& p) {
  using a_frame_detail::cross;
  a_frame_detail::validate(p);
  const Eigen::Vector2d e = boom_axis(p), s = p.boom_length * e, tip = p.heel + s;
  AFrameRest r;
  r.luffing_length = (p.top - tip).norm();
  r.backstay_length = (p.deck_point - p.top).norm();
  if (r.luffing_length <= 0.0 || r.backstay_length <= 0.0) {
    throw std::invalid_argument("a-frame crane: a wire of zero length at rest");
  }
  r.luffing_direction = (p.top - tip) / r.luffing_length;
  r.backstay_direction = (p.deck_point - p.top) / r.backstay_length;
  const double g = p.gravity, W = p.mass_per_length * p.boom_length * g;
  const double gravity_moment_B =
      cross(0.5 * s, Eigen::Vector2d(0.0, -W)) + cross(s, Eigen::Vector2d(0.0, -p.tip_mass * g));
  const double arm_L = cross(s, r.luffing_direction);
  r.luffing_tension = arm_L == 0.0 ? 0.0 : -gravity_moment_B / arm_L;
  if (!(r.luffing_tension > 0.0)) {
    throw std::invalid_argument("a-frame crane: the luffing wires would be slack at rest "
                                "(tension " + std::to_string(r.luffing_tension) + " N)");
  }
  const Eigen::Vector2d rT = p.top - p.pivot, rG = p.a_frame_cg - p.pivot;
  const double moment_P = cross(rT, -r.luffing_tension * r.luffing_direction) +
                          cross(rG, Eigen::Vector2d(0.0, -p.a_frame_mass * g));
  const double arm_B = cross(rT, r.backstay_direction);
  r.backstay_tension = arm_B == 0.0 ? 0.0 : -moment_P / arm_B;
  if (!(r.backstay_tension > 0.0)) {
    throw std::invalid_argument("a-frame crane: the backstays would be slack at rest "
                                "(tension " + std::to_string(r.backstay_tension) + " N)");
  }
  r.luffing_unstretched =
      r.luffing_length - r.luffing_tension / (p.luffing_count * p.luffing_stiffness);
  r.backstay_unstretched =
      r.backstay_length - r.backstay_tension / (p.backstay_count * p.backstay_stiffness);
  if (r.luffing_unstretched <= 0.0 || r.backstay_unstretched <= 0.0) {
    throw std::invalid_argument("a-frame crane: a wire too soft (unstretched length <= 0)");
  }
  return r;
}

// The crane with its unset (negative) unstretched lengths replaced by those of rest_tensions.
inline AFrameCrane with_rest_lengths(AFrameCrane p) {
  if (p.luffing_unstretched < 0.0 || p.backstay_unstretched < 0.0) {
    const AFrameRest r = rest_tensions(p);
    if (p.luffing_unstretched < 0.0) p.luffing_unstretched = r.luffing_unstretched;
    if (p.backstay_unstretched < 0.0) p.backstay_unstretched = r.backstay_unstretched;
  }
  return p;
}

// ---------------------------------------------------------------- 2. rigid boom, exact
// One wire set (n wires) between two points, r = their difference, ℓ = |r|, d = r/ℓ:
//   E(r) = ½ n k (ℓ − L0)² for ℓ > L0, else 0 (tension only); t = n k max(ℓ − L0, 0);
//   ∂E/∂r = t d (∂ℓ/∂r = dᵀ);
//   ∂²E/∂r² = n k [ℓ > L0] d dᵀ + (t/ℓ)(I − d dᵀ) (∂d/∂r = (I − d dᵀ)/ℓ).
struct WireEnergy {
  double energy = 0.0, tension = 0.0;
  Eigen::Vector2d gradient = Eigen::Vector2d::Zero();
  Eigen::Matrix2d hessian = Eigen::Matrix2d::Zero();
};
inline WireEnergy wire_energy(const Eigen::Vector2d& r, double nk, double L0) {
  WireEnergy w;
  const double l = r.norm();
  const Eigen::Vector2d d = r / l;
  const Eigen::Matrix2d ddT = d * d.transpose();
  if (l > L0) {
    w.tension = nk * (l - L0);
    w.energy = 0.5 * nk * (l - L0) * (l - L0);
    w.hessian = nk * ddT;
  }
  w.gradient = w.tension * d;
  w.hessian += w.tension / l * (Eigen::Matrix2d::Identity() - ddT);
  return w;
}

struct RigidEnergy {
  double potential = 0.0;
  Eigen::Vector2d gradient = Eigen::Vector2d::Zero();  // ∂V/∂(β, ψ)
  Eigen::Matrix2d hessian = Eigen::Matrix2d::Zero();
};

// V(β, ψ) = E_L(tip − T) + E_B(T − D) + ρA L g y_mid + m_tip g y_tip + m_A g y_G (heights from the
// global origin), with the exact kinematics s = L(cos(α + β), sin(α + β)), tip = B + s,
// r_T = R(ψ)(T₀ − P), T = P + r_T, r_G = R(ψ)(G₀ − P). Derivatives: a point rotating about its pin
// at r has ∂/∂angle = Ĩr and ∂²/∂angle² = −r; so with a = Ĩs, b = Ĩr_T, for a wire r(q):
// ∂²E/∂qᵢ∂qⱼ = r,ᵢᵀ E_rr r,ⱼ + E_r · r,ᵢⱼ (chain rule). Luffing r = tip − T: r,β = a, r,ψ = −b,
// r,ββ = −s, r,ψψ = r_T, r,βψ = 0; backstay r = T − D: r,ψ = b, r,ψψ = −r_T. Gravity m g y(q):
// derivatives m g (Ĩr)_y = m g r_x and −m g r_y. Unset unstretched lengths: those of rest_tensions.
inline RigidEnergy rigid_energy(const AFrameCrane& crane, double beta, double psi) {
  const AFrameCrane p = with_rest_lengths(crane);
  a_frame_detail::validate(p);
  const double L = p.boom_length, g = p.gravity, mb = p.mass_per_length * L;
  const Eigen::Vector2d s = L * Eigen::Vector2d(std::cos(p.boom_angle + beta),
                                                std::sin(p.boom_angle + beta));
  const Eigen::Vector2d rT = a_frame_detail::rotate(p.top - p.pivot, psi);
  const Eigen::Vector2d rG = a_frame_detail::rotate(p.a_frame_cg - p.pivot, psi);
  const Eigen::Vector2d a = a_frame_detail::perp(s), b = a_frame_detail::perp(rT);
  const WireEnergy lu = wire_energy(p.heel + s - p.pivot - rT,
                                    p.luffing_count * p.luffing_stiffness, p.luffing_unstretched);
  const WireEnergy bs =
      wire_energy(p.pivot + rT - p.deck_point, p.backstay_count * p.backstay_stiffness,
                  p.backstay_unstretched);
  RigidEnergy out;
  out.potential = lu.energy + bs.energy + mb * g * (p.heel.y() + 0.5 * s.y()) +
                  p.tip_mass * g * (p.heel.y() + s.y()) +
                  p.a_frame_mass * g * (p.pivot.y() + rG.y());
  out.gradient << lu.gradient.dot(a) + (0.5 * mb + p.tip_mass) * g * s.x(),
      (bs.gradient - lu.gradient).dot(b) + p.a_frame_mass * g * rG.x();
  out.hessian(0, 0) =
      a.dot(lu.hessian * a) - lu.gradient.dot(s) - (0.5 * mb + p.tip_mass) * g * s.y();
  out.hessian(1, 1) = b.dot((lu.hessian + bs.hessian) * b) + (lu.gradient - bs.gradient).dot(rT) -
                      p.a_frame_mass * g * rG.y();
  out.hessian(0, 1) = out.hessian(1, 0) = -a.dot(lu.hessian * b);
  return out;
}

inline double rigid_potential(const AFrameCrane& p, double beta, double psi) {
  return rigid_energy(p, beta, psi).potential;
}

// Newton on ∇V = 0 from (0, 0), with the analytic Hessian (checked against finite differences of
// rigid_potential in the self-tests); every iterate's Hessian must be positive definite.
inline Eigen::Vector2d rigid_static_equilibrium(const AFrameCrane& crane) {
  const AFrameCrane p = with_rest_lengths(crane);
  Eigen::Vector2d q = Eigen::Vector2d::Zero();
  for (int iteration = 0; iteration < 50; ++iteration) {
    const RigidEnergy s = rigid_energy(p, q(0), q(1));
    const Eigen::LDLT<Eigen::Matrix2d> ldlt(s.hessian);
    if (ldlt.info() != Eigen::Success || !ldlt.isPositive() || s.hessian.determinant() <= 0.0) {
      throw std::runtime_error("a-frame crane (rigid): Hessian not positive definite on the way");
    }
    const Eigen::Vector2d step = ldlt.solve(s.gradient);
    q -= step;
    if (step.lpNorm<Eigen::Infinity>() < 1e-14) return q;
  }
  throw std::runtime_error("a-frame crane (rigid): Newton did not converge");
}

// Small oscillation about the equilibrium: Lagrange with T = ½(I_B β̇² + I_P ψ̇²) (the boom turns
// about B, the A-frame about P; no inertia coupling) gives det(H − ω² diag(I_B, I_P)) = 0;
// solved as the symmetric M^(−1/2) H M^(−1/2). Ascending ω [rad/s]; throws if the equilibrium is
// unstable.
inline Eigen::Vector2d rigid_frequencies(const AFrameCrane& crane) {
  const AFrameCrane p = with_rest_lengths(crane);
  const Eigen::Vector2d q = rigid_static_equilibrium(p);
  const Eigen::Matrix2d H = rigid_energy(p, q(0), q(1)).hessian;
  const Eigen::Vector2d m(boom_pivot_inertia(p), a_frame_pivot_inertia(p));
  Eigen::Matrix2d A;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) A(i, j) = H(i, j) / std::sqrt(m(i) * m(j));
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver{Eigen::MatrixXd(A)};
  if (solver.info() != Eigen::Success || !(solver.eigenvalues()(0) > 0.0)) {
    throw std::runtime_error("a-frame crane (rigid): equilibrium not stable");
  }
  return solver.eigenvalues().cwiseSqrt();
}

// ---------------------------------------------------------------- 3. elastic boom, linearised
// Coordinates: the pinned boom's nodal DOFs (u, v, φ) in the boom frame (x along e = (cos α,
// sin α) from B, y along n = Ĩe) at x = iL/N, heel u₀, v₀ removed, then ψ (last). The boom's
// rigid rotation β about B is not a separate coordinate: it is the FE motion v = βx, φ = β.
// Potential, moderate rotations (von Kármán strain ε = u' + ½w'², as pinned_boom_reference):
//   U = ∫ ½EA ε² + ½EI w''² dx, loads dead (gravity) at positions linear in (u, w), the wires by
//   E(r) above, the A-frame a rigid body turning exactly about P.
// Reference state: the straight boom at α and the A-frame at rest, with the prestress of the rest
// equilibrium (rest_tensions): the wire tensions T_L, T_B and the boom's axial force
//   N(x) = e · [ρA (L − x) g⃗ + m_tip g⃗ + T_L u_L]   (tension positive; axial balance of (x, L]),
// taken at the rest geometry (the standard prestressed linearisation: K = K₀ + K_σ(rest
// prestress), all at the straight boom at α and the A-frame at rest). Not fed back: the elastic
// equilibrium's own displacement x* from the rest state (its sag, elastic_static_deflection: 1.4 cm
// at the defaults' tip), which would turn the wires by |x*|/ℓ (a change O(n k |x*|/ℓ) of their
// spring terms, ~1e-4 relative at the defaults) and move the loads' lever arms; it vanishes with a
// stiff boom, where the rigid model (exact) is recovered. Also left out: Green's ½u'² (the axial
// geometric stiffness N∫u'δu', relative N/EA ~ 1e-4), as in pinned_boom_reference.
// K contains:
//  - boom: EA∫N_u'ᵀN_u' + EI∫N_v''ᵀN_v'' + ∫N(x) N_v'ᵀN_v' dx (the last from EA ε* = N at the
//    equilibrium: ∂²/∂w² of ½EA(ε* + w'²/2 + …)² gives N w'δw'). For the rigid motion w = βx it is
//    ½β²∫N dx = ½β² Σ rᵢ·Fᵢ (∫₀ᴸN dx = Σ (e·Fᵢ) xᵢ over the boom's forces at xᵢ: weight, tip
//    weight, luffing pull): exactly the second-order load terms of the exact rotation (a point at
//    r from B moves by −½β²r, so a force F adds ½β² r·F) — they are in N(x), not added again;
//  - luffing wires: (n_L k_L d dᵀ + (T_L/ℓ_L)(I − d dᵀ)) on Δ = E(u_N, v_N) − ψ Ĩ(T − P), the
//    relative displacement of the tip (E = [e n] boom → global) and of T;
//  - backstays: (n_B k_B d dᵀ + (T_B/ℓ_B)(I − d dᵀ)) on T's displacement ψ Ĩ(T − P) (D fixed);
//  - A-frame load terms: its forces at rest, −T_L u_L and T_B u_B at T and m_A g⃗ at G_A, each
//    ½ψ² r·F (r from P), so K_ψψ += (T − P)·(T_B u_B − T_L u_L) + (G_A − P)·m_A g⃗.
// M: consistent ρA∫(N_uᵀN_u + N_vᵀN_v), m_tip on u_N, v_N, I_P on ψ. 4-point Gauss–Legendre per
// element, exact for these integrands (degree ≤ 6; N(x) is linear).
// f = −∇V at the rest state: consistent gravity ρA∫N_vᵀ g_local, the tip's m_tip g⃗ + T_L u_L
// (boom frame), and on ψ the moment about P of the A-frame's rest forces; the rest tensions
// balance gravity's moments, so f does no work on the rigid β and on ψ (round-off).
struct AFrameElastic {
  Eigen::MatrixXd K, M;  // over 3(N + 1) − 2 boom DOFs, then ψ
  Eigen::VectorXd f;
  int elements = 0;
  AFrameRest rest;
  Eigen::Index psi_index() const { return K.rows() - 1; }
  // Nodal (u, v, φ) of nodes 0..N (heel u, v as zeros) from a full coordinate vector.
  Eigen::VectorXd boom_nodal(const Eigen::VectorXd& x) const {
    Eigen::VectorXd full = Eigen::VectorXd::Zero(x.size() + 1);
    full.tail(x.size() - 1) = x.head(x.size() - 1);
    return full;
  }
};

inline AFrameElastic assemble_a_frame_crane(const AFrameCrane& p, int elements) {
  using a_frame_detail::perp;
  if (elements < 1) throw std::invalid_argument("a-frame crane: elements >= 1");
  const AFrameRest rest = rest_tensions(p);
  const double L = p.boom_length, h = L / elements, rhoA = p.mass_per_length;
  const Eigen::Vector2d e = boom_axis(p), n = perp(e), g_vec(0.0, -p.gravity);
  Eigen::Matrix2d E;
  E << e, n;
  const Eigen::Vector2d g_local = E.transpose() * g_vec;
  const Eigen::Vector2d tip_pull = rest.luffing_tension * rest.luffing_direction;
  const double N_tip = e.dot(p.tip_mass * g_vec + tip_pull), N_slope = rhoA * e.dot(g_vec);

  const int n_boom = 3 * (elements + 1), n_full = n_boom + 1, psi = n_boom;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n_full, n_full), M = K;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n_full);
  const double s1 = std::sqrt(3.0 / 7.0 - 2.0 / 7.0 * std::sqrt(6.0 / 5.0));
  const double s2 = std::sqrt(3.0 / 7.0 + 2.0 / 7.0 * std::sqrt(6.0 / 5.0));
  const double w1 = (18.0 + std::sqrt(30.0)) / 36.0, w2 = (18.0 - std::sqrt(30.0)) / 36.0;
  const double gx[4] = {-s2, -s1, s1, s2}, gw[4] = {w2, w1, w1, w2};
  for (int el = 0; el < elements; ++el) {
    for (int q = 0; q < 4; ++q) {
      const double xi = 0.5 * (1.0 + gx[q]), wx = 0.5 * gw[q] * h, x = (el + xi) * h;
      // Element DOFs (u1, v1, φ1, u2, v2, φ2): linear Nu, Hermite Nv, derivatives in x.
      Eigen::Matrix<double, 1, 6> Nu, dNu, Nv, dNv, ddNv;
      Nu << 1.0 - xi, 0, 0, xi, 0, 0;
      dNu << -1.0 / h, 0, 0, 1.0 / h, 0, 0;
      Nv << 0, 1 - 3 * xi * xi + 2 * xi * xi * xi, h * (xi - 2 * xi * xi + xi * xi * xi), 0,
          3 * xi * xi - 2 * xi * xi * xi, h * (xi * xi * xi - xi * xi);
      dNv << 0, 6 * (xi * xi - xi) / h, 1 - 4 * xi + 3 * xi * xi, 0, 6 * (xi - xi * xi) / h,
          3 * xi * xi - 2 * xi;
      ddNv << 0, (12 * xi - 6) / (h * h), (6 * xi - 4) / h, 0, (6 - 12 * xi) / (h * h),
          (6 * xi - 2) / h;
      const double N_x = N_tip + N_slope * (L - x);
      K.block<6, 6>(3 * el, 3 * el) += wx * (p.EA * dNu.transpose() * dNu +
                                             p.EI * ddNv.transpose() * ddNv +
                                             N_x * dNv.transpose() * dNv);
      M.block<6, 6>(3 * el, 3 * el) += wx * rhoA * (Nu.transpose() * Nu + Nv.transpose() * Nv);
      f.segment<6>(3 * el) +=
          wx * rhoA * (Nu.transpose() * g_local(0) + Nv.transpose() * g_local(1));
    }
  }
  const int tip = 3 * elements;
  M(tip, tip) += p.tip_mass;
  M(tip + 1, tip + 1) += p.tip_mass;
  M(psi, psi) += a_frame_pivot_inertia(p);
  f.segment<2>(tip) += E.transpose() * (p.tip_mass * g_vec + tip_pull);

  const Eigen::Vector2d rT = p.top - p.pivot, rG = p.a_frame_cg - p.pivot, bT = perp(rT);
  const Eigen::Vector2d backstay_pull = rest.backstay_tension * rest.backstay_direction;
  auto wire_matrix = [](const Eigen::Vector2d& d, double nk, double tension, double length) {
    const Eigen::Matrix2d ddT = d * d.transpose();
    return Eigen::Matrix2d(nk * ddT + tension / length * (Eigen::Matrix2d::Identity() - ddT));
  };
  const Eigen::Matrix2d HL =
      wire_matrix(rest.luffing_direction, p.luffing_count * p.luffing_stiffness,
                  rest.luffing_tension, rest.luffing_length);
  const Eigen::Matrix2d HB = wire_matrix(rest.backstay_direction,
                                         p.backstay_count * p.backstay_stiffness,
                                         rest.backstay_tension, rest.backstay_length);
  Eigen::Matrix<double, 2, 3> G;  // Δ = G (u_N, v_N, ψ)
  G << E, -bT;
  const int z[3] = {tip, tip + 1, psi};
  const Eigen::Matrix3d KL = G.transpose() * HL * G;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) K(z[i], z[j]) += KL(i, j);
  }
  K(psi, psi) +=
      bT.dot(HB * bT) + rT.dot(backstay_pull - tip_pull) + rG.dot(p.a_frame_mass * g_vec);
  f(psi) += a_frame_detail::cross(rT, backstay_pull - tip_pull) +
            a_frame_detail::cross(rG, p.a_frame_mass * g_vec);

  const int m = n_full - 2;  // pinned heel: drop u₀, v₀
  return {K.bottomRightCorner(m, m), M.bottomRightCorner(m, m), f.tail(m), elements, rest};
}

// The lowest `count` ω [rad/s] of K x = ω² M x, ascending; throws if K is not positive definite
// (the rest state unstable); round-off negatives of a near-zero eigenvalue are clamped to 0. Each
// ω² carries an absolute round-off ~ε λ_max (λ_max: the stiffest element mode), ~1e-9 relative
// on the defaults' lowest mode at N = 16, more on an artificially stiff boom.
inline Eigen::VectorXd elastic_frequencies(const AFrameCrane& p, int elements, int count) {
  const AFrameElastic s = assemble_a_frame_crane(p, elements);
  if (count < 1 || count > s.K.rows()) throw std::invalid_argument("a-frame crane: count");
  if (Eigen::LLT<Eigen::MatrixXd>(s.K).info() != Eigen::Success) {
    throw std::runtime_error("a-frame crane (elastic): stiffness not positive definite");
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(s.K, s.M);
  if (solver.info() != Eigen::Success) {
    throw std::runtime_error("a-frame crane: eigensolver failed");
  }
  return solver.eigenvalues().head(count).cwiseMax(0.0).cwiseSqrt();
}

struct AFrameStatic {
  Eigen::Vector2d tip_displacement;   // (u, v) at the boom tip, boom frame, m
  double a_frame_rotation = 0.0;      // ψ, rad
  double luffing_tension_change = 0.0;   // total, N: n_L k_L × the wires' stretch
  double backstay_tension_change = 0.0;  // total, N
  Eigen::VectorXd nodal;              // (u, v, φ) of nodes 0..N
};

// The linearised equilibrium ∇V(rest) + K x = 0, i.e. K x = f: the displacement from the straight
// boom at α and the A-frame at rest (wires at their rest tensions) to the elastic equilibrium, to
// first order in the loads — the boom's sag and compression under its weight, the tip mass and
// the rest pulls, and the rotations β, ψ that this asks of the wires. (K's prestress terms add the
// beam-column effect; that is of second order, as the geometry terms left out of K.)
inline AFrameStatic elastic_static_deflection(const AFrameCrane& p, int elements) {
  const AFrameElastic s = assemble_a_frame_crane(p, elements);
  const Eigen::LLT<Eigen::MatrixXd> llt(s.K);
  if (llt.info() != Eigen::Success) {
    throw std::runtime_error("a-frame crane (elastic): stiffness not positive definite");
  }
  const Eigen::VectorXd x = llt.solve(s.f);
  AFrameStatic out;
  out.nodal = s.boom_nodal(x);
  out.tip_displacement = out.nodal.segment<2>(3 * elements);
  out.a_frame_rotation = x(s.psi_index());
  const Eigen::Vector2d e = boom_axis(p);
  const Eigen::Vector2d dT = out.a_frame_rotation * a_frame_detail::perp(p.top - p.pivot);
  const Eigen::Vector2d d_tip =
      out.tip_displacement(0) * e + out.tip_displacement(1) * a_frame_detail::perp(e);
  out.luffing_tension_change =
      -p.luffing_count * p.luffing_stiffness * s.rest.luffing_direction.dot(d_tip - dT);
  out.backstay_tension_change =
      -p.backstay_count * p.backstay_stiffness * s.rest.backstay_direction.dot(dT);
  return out;
}

}  // namespace ffrf::test
