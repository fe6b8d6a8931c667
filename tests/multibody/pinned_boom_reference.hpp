// Independent reference of a planar boom pinned at its heel and held by an elastic (luffing) wire:
// the second method the crane's code is checked against. Only Eigen (its solvers compiled once in
// linalg/) and the standard library are used — nothing of fem/, modal/ or multibody/ — and every formula is written here from its
// textbook definition.
//
// Model: linear small motion about the straight boom, boom frame x from heel to tip, y transverse.
// Euler–Bernoulli bending (EI w'''' + ρA ẅ = 0) and a bar (EA u'' = ρA ü). Heel: pin (u = v = 0,
// rotation free). Wire at x = a: a spring k d dᵀ along its unit direction d (from the attachment
// towards the fixed anchor) plus the geometric stiffness of its tension (T/ℓ)(I − d dᵀ); optional
// lumped tip mass, and a uniform axial force P (tension positive: geometric stiffness P∫w'δw'dx).
// 1. Finite elements (e.g. Cook, Malkus, Plesha & Witt, "Concepts and Applications of FEA", bar
//    and beam elements): linear bar, cubic Hermite beam, consistent mass M = ρA∫NᵀN dx, stiffness
//    K = EA∫N'ᵀN' dx + EI∫N''ᵀN'' dx + P∫N_v'ᵀN_v' dx, consistent load f = ∫Nᵀq dx, all
//    integrated by 4-point Gauss–Legendre quadrature (exact for these polynomial degrees).
// 2. Exact solutions (transverse wire at the tip): the frequency equations of the pinned–spring
//    beam and bar, solved by scanning and bisection, and the static deflection under uniform load.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>

// Eigen's own dense eigen solvers, compiled once for the project (the same Eigen code, declared extern).
#include "linalg/dense_solvers.hpp"

namespace ffrf::test {

// Defaults: the boom and wire of the project's reference crane (cases/paper_floating_crane.toml).
struct PinnedBoom {
  double length = 120.0;             // m
  double EI = 2.1e11 * 11.4;         // N m²
  double EA = 2.1e11 * 1.27;         // N
  double mass_per_length = 1.0e4;    // kg/m (ρA)
  double wire_stiffness = 2.0e8;     // N/m (k)
  Eigen::Vector2d wire_direction_local{0.0, 1.0};  // unit d, boom frame, attachment → anchor
  double wire_point = -1.0;          // m from the heel; negative (default): at the tip
  double tip_mass = 0.0;             // kg
  double tip_rotary_inertia = 0.0;   // kg m²
  double wire_tension = 0.0;         // N (T)
  double wire_length = 1.0;          // m (ℓ)
  double axial_force_uniform = 0.0;  // N (P, tension positive)

  double attachment() const { return wire_point < 0.0 ? length : wire_point; }
};

// ---------------------------------------------------------------- finite elements
// DOFs (u, v, φ) per node i = 0..N at x = i L/N; the heel's u0, v0 are removed.
struct PinnedBoomFe {
  Eigen::MatrixXd K, M;  // over the free DOFs (3(N + 1) − 2)
  Eigen::VectorXd f;     // consistent load of `assemble_pinned_boom` (zero unless given loads)
  int elements = 0;
  // Nodal DOF vector (3(N + 1), heel u, v included as zeros) from a free-DOF vector.
  Eigen::VectorXd expand(const Eigen::VectorXd& free) const {
    Eigen::VectorXd full = Eigen::VectorXd::Zero(free.size() + 2);
    full.tail(free.size()) = free;
    return full;
  }
};

// Assembles K, M and the load of a uniform load q (force per length, boom frame) plus a force at
// the tip and the tip mass's weight tip_mass × g_local.
inline PinnedBoomFe assemble_pinned_boom(const PinnedBoom& b, int elements,
                                         const Eigen::Vector2d& q = Eigen::Vector2d::Zero(),
                                         const Eigen::Vector2d& tip_force = Eigen::Vector2d::Zero(),
                                         const Eigen::Vector2d& g_local = Eigen::Vector2d::Zero()) {
  if (elements < 1 || b.length <= 0.0 || b.mass_per_length <= 0.0) {
    throw std::invalid_argument("pinned boom: elements ≥ 1, positive length and mass");
  }
  const double h = b.length / elements;
  const double wire_node_real = b.attachment() / h;
  const long wire_node = std::lround(wire_node_real);
  if (std::abs(wire_node_real - static_cast<double>(wire_node)) > 1e-9 || wire_node < 1 ||
      wire_node > elements) {
    throw std::invalid_argument("pinned boom: the wire point must be at a node (not the heel)");
  }
  const int n_full = 3 * (elements + 1);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n_full, n_full);
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n_full, n_full);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n_full);

  // 4-point Gauss–Legendre on [0, 1].
  const double s1 = std::sqrt(3.0 / 7.0 - 2.0 / 7.0 * std::sqrt(6.0 / 5.0));
  const double s2 = std::sqrt(3.0 / 7.0 + 2.0 / 7.0 * std::sqrt(6.0 / 5.0));
  const double w1 = (18.0 + std::sqrt(30.0)) / 36.0, w2 = (18.0 - std::sqrt(30.0)) / 36.0;
  const double gx[4] = {-s2, -s1, s1, s2}, gw[4] = {w2, w1, w1, w2};

  Eigen::Matrix<double, 6, 6> ke = Eigen::Matrix<double, 6, 6>::Zero(), me = ke;
  Eigen::Matrix<double, 6, 1> fe = Eigen::Matrix<double, 6, 1>::Zero();
  for (int g = 0; g < 4; ++g) {
    const double xi = 0.5 * (1.0 + gx[g]), wx = 0.5 * gw[g] * h;  // dx = h dξ
    // Element DOFs (u1, v1, φ1, u2, v2, φ2); Nu axial, Nv transverse (Hermite), derivatives in x.
    Eigen::Matrix<double, 1, 6> Nu, dNu, Nv, dNv, ddNv;
    Nu << 1.0 - xi, 0, 0, xi, 0, 0;
    dNu << -1.0 / h, 0, 0, 1.0 / h, 0, 0;
    Nv << 0, 1 - 3 * xi * xi + 2 * xi * xi * xi, h * (xi - 2 * xi * xi + xi * xi * xi), 0,
        3 * xi * xi - 2 * xi * xi * xi, h * (xi * xi * xi - xi * xi);
    dNv << 0, (-6 * xi + 6 * xi * xi) / h, 1 - 4 * xi + 3 * xi * xi, 0, (6 * xi - 6 * xi * xi) / h,
        3 * xi * xi - 2 * xi;
    ddNv << 0, (-6 + 12 * xi) / (h * h), (-4 + 6 * xi) / h, 0, (6 - 12 * xi) / (h * h),
        (6 * xi - 2) / h;
    me += wx * b.mass_per_length * (Nu.transpose() * Nu + Nv.transpose() * Nv);
    ke += wx * (b.EA * dNu.transpose() * dNu + b.EI * ddNv.transpose() * ddNv +
                b.axial_force_uniform * dNv.transpose() * dNv);
    fe += wx * (Nu.transpose() * q(0) + Nv.transpose() * q(1));
  }
  for (int e = 0; e < elements; ++e) {
    K.block<6, 6>(3 * e, 3 * e) += ke;
    M.block<6, 6>(3 * e, 3 * e) += me;
    f.segment<6>(3 * e) += fe;
  }
  const int tip = 3 * elements, wire = 3 * static_cast<int>(wire_node);
  const Eigen::Vector2d d = b.wire_direction_local;
  if (std::abs(d.norm() - 1.0) > 1e-12) throw std::invalid_argument("pinned boom: |d| must be 1");
  const Eigen::Matrix2d ddT = d * d.transpose();
  K.block<2, 2>(wire, wire) += b.wire_stiffness * ddT +
                               b.wire_tension / b.wire_length * (Eigen::Matrix2d::Identity() - ddT);
  M(tip, tip) += b.tip_mass;
  M(tip + 1, tip + 1) += b.tip_mass;
  M(tip + 2, tip + 2) += b.tip_rotary_inertia;
  f.segment<2>(tip) += tip_force + b.tip_mass * g_local;

  const int n = n_full - 2;  // pinned heel: drop u0, v0
  return {K.bottomRightCorner(n, n), M.bottomRightCorner(n, n), f.tail(n), elements};
}

struct PinnedBoomModes {
  Eigen::VectorXd omega;           // rad/s, ascending (negative eigenvalues clamped to 0)
  Eigen::MatrixXd shapes;          // columns: M-normalised modes over the nodal DOFs (3(N + 1))
  Eigen::VectorXd axial_fraction;  // share of each mode's kinetic energy in the u DOFs
};

inline PinnedBoomModes natural_modes_fe(const PinnedBoom& b, int elements) {
  const PinnedBoomFe fe = assemble_pinned_boom(b, elements);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(fe.K, fe.M);
  if (solver.info() != Eigen::Success) throw std::runtime_error("pinned boom: eigensolver failed");
  const Eigen::Index n = fe.K.rows();
  PinnedBoomModes modes{Eigen::VectorXd(n), Eigen::MatrixXd(n + 2, n), Eigen::VectorXd(n)};
  for (Eigen::Index j = 0; j < n; ++j) {
    modes.omega(j) = std::sqrt(std::max(solver.eigenvalues()(j), 0.0));
    const Eigen::VectorXd x = solver.eigenvectors().col(j);
    modes.shapes.col(j) = fe.expand(x);
    Eigen::VectorXd axial = Eigen::VectorXd::Zero(n);  // u DOFs of nodes 1..N: 1, 4, 7, ...
    for (Eigen::Index i = 1; i < n; i += 3) axial(i) = x(i);
    modes.axial_fraction(j) = axial.dot(fe.M * axial) / x.dot(fe.M * x);
  }
  return modes;
}

// The lowest `count` frequencies [rad/s] of all in-plane modes.
inline Eigen::VectorXd natural_frequencies_fe(const PinnedBoom& b, int elements, int count) {
  const Eigen::VectorXd omega = natural_modes_fe(b, elements).omega;
  if (count < 0 || count > omega.size()) throw std::invalid_argument("pinned boom: count");
  return omega.head(count);
}

// The lowest `count` frequencies of the modes mostly bending (axial_fraction < 1/2); with a
// transverse wire the two families decouple exactly (fractions 0 or 1).
inline Eigen::VectorXd bending_frequencies_fe(const PinnedBoom& b, int elements, int count) {
  const PinnedBoomModes modes = natural_modes_fe(b, elements);
  std::vector<double> out;
  for (Eigen::Index j = 0; j < modes.omega.size() && static_cast<int>(out.size()) < count; ++j) {
    if (modes.axial_fraction(j) < 0.5) out.push_back(modes.omega(j));
  }
  if (static_cast<int>(out.size()) < count) throw std::invalid_argument("pinned boom: count");
  return Eigen::Map<const Eigen::VectorXd>(out.data(), count);
}

struct PinnedBoomStatic {
  Eigen::Vector2d tip_displacement;  // (u, v) at the tip, boom frame
  double heel_rotation = 0.0;        // φ at the heel
  double wire_force = 0.0;  // change of wire tension, −k dᵀu_a (positive: the wire stretches)
  Eigen::VectorXd nodal;    // (u, v, φ) of nodes 0..N
};

// Static solution K x = f under gravity (acceleration per unit mass, boom frame: load ρA g and
// tip_mass g) and a force at the tip, from the straight reference state (an equilibrium with the
// wire's tension T; T's own force is not a load).
inline PinnedBoomStatic static_deflection_fe(const PinnedBoom& b, int elements,
                                             const Eigen::Vector2d& gravity_local,
                                             const Eigen::Vector2d& tip_force_local) {
  const PinnedBoomFe fe = assemble_pinned_boom(b, elements, b.mass_per_length * gravity_local,
                                               tip_force_local, gravity_local);
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(fe.K);
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive() ||
      ldlt.vectorD().cwiseAbs().minCoeff() <= 1e-14 * ldlt.vectorD().cwiseAbs().maxCoeff()) {
    throw std::invalid_argument("pinned boom: stiffness singular (no wire stiffness?)");
  }
  PinnedBoomStatic out;
  out.nodal = fe.expand(ldlt.solve(fe.f));
  out.tip_displacement = out.nodal.segment<2>(3 * elements);
  out.heel_rotation = out.nodal(2);
  const long wire = std::lround(b.attachment() / (b.length / elements));
  out.wire_force = -b.wire_stiffness * b.wire_direction_local.dot(out.nodal.segment<2>(3 * wire));
  return out;
}

// ---------------------------------------------------------------- exact solutions
// The positive roots z of `f` above 0, scanned in steps `dz` and bisected to the last bit
// (|hi − lo| ≤ 4 ε z, well inside 1e-13 relative); `f` must change sign at each root.
inline std::vector<double> positive_roots(const std::function<double(double)>& f, int count,
                                          double dz = 0.01) {
  std::vector<double> roots;
  double lo = 1e-3, f_lo = f(lo);
  while (static_cast<int>(roots.size()) < count) {
    const double hi = lo + dz, f_hi = f(hi);
    if ((f_lo < 0.0) != (f_hi < 0.0)) {
      double a = lo, b = hi, fa = f_lo;
      while (b - a > 4.0 * std::numeric_limits<double>::epsilon() * b) {
        const double m = 0.5 * (a + b), fm = f(m);
        if (fm == 0.0) { a = b = m; break; }
        if ((fa < 0.0) == (fm < 0.0)) { a = m; fa = fm; } else { b = m; }
      }
      roots.push_back(0.5 * (a + b));
    }
    lo = hi;
    f_lo = f_hi;
  }
  return roots;
}

inline void require_transverse_tip_wire(const PinnedBoom& b) {
  if (std::abs(b.wire_direction_local.x()) > 1e-12 || std::abs(b.attachment() - b.length) > 0.0 ||
      b.tip_mass != 0.0 || b.tip_rotary_inertia != 0.0 || b.axial_force_uniform != 0.0) {
    throw std::invalid_argument("pinned boom: exact case is d = (0, ±1) at a bare tip, P = 0");
  }
}

// Bending, exact. Derivation: w(x) = A sin βx + B cos βx + C sinh βx + D cosh βx, β⁴ = ρA ω²/EI.
// Energy ½∫EI w''² dx + ½ k w(L)²: its variation has the boundary terms [EI w'' δw']₀ᴸ,
// −[EI w''' δw]₀ᴸ and k w(L) δw(L), so with δw(L), δw'(L) free, at x = L: w'' = 0 and
// −EI w''' + k w = 0, i.e. EI w''' = k w.
// x = 0: w = 0 and w'' = 0 ⇒ B + D = 0, −B + D = 0 ⇒ B = D = 0. With λ = βL, κ = kL³/EI:
//   w''(L) = 0:          −A sin λ + C sinh λ = 0
//   EI w'''(L) = k w(L): A(−λ³ cos λ − κ sin λ) + C(λ³ cosh λ − κ sinh λ) = 0
// det = λ³(sinh λ cos λ − sin λ cosh λ) + 2κ sin λ sinh λ = 0, divided by cosh λ (no overflow):
//   λ³(tanh λ cos λ − sin λ) + 2κ sin λ tanh λ = 0.
// κ = 0: tan λ = tanh λ (pinned–free, plus the rigid rotation λ = 0); κ → ∞: sin λ = 0 (pinned–
// pinned). The wire's tension acts only axially here (d ⊥ boom). ω = (λ/L)² √(EI/ρA).
// Returns the lowest `count` bending frequencies [rad/s]; with k = 0 the first is the rigid 0.
inline Eigen::VectorXd natural_frequencies_analytic(const PinnedBoom& b, int count) {
  require_transverse_tip_wire(b);
  const double kappa = b.wire_stiffness * std::pow(b.length, 3) / b.EI;
  const bool rigid = b.wire_stiffness == 0.0;
  const std::vector<double> lambda = positive_roots(
      [kappa](double z) {
        const double t = std::tanh(z);
        return z * z * z * (t * std::cos(z) - std::sin(z)) + 2.0 * kappa * std::sin(z) * t;
      },
      count - (rigid ? 1 : 0));
  Eigen::VectorXd omega = Eigen::VectorXd::Zero(count);
  const double c = std::sqrt(b.EI / b.mass_per_length) / (b.length * b.length);
  for (std::size_t i = 0; i < lambda.size(); ++i) {
    omega(static_cast<Eigen::Index>(i) + (rigid ? 1 : 0)) = lambda[i] * lambda[i] * c;
  }
  return omega;
}

// Axial, exact: u = sin γx (u(0) = 0), EA u'(L) = −k_a u(L) with k_a = T/ℓ (the tension's
// stiffness along the boom when d ⊥ boom): μ cos μ + (k_a L/EA) sin μ = 0, μ = γL,
// ω = (μ/L)√(EA/ρA). k_a = 0: μ = (2n − 1)π/2.
inline Eigen::VectorXd axial_frequencies_analytic(const PinnedBoom& b, int count) {
  require_transverse_tip_wire(b);
  const double alpha = b.wire_tension / b.wire_length * b.length / b.EA;
  const std::vector<double> mu = positive_roots(
      [alpha](double z) { return z * std::cos(z) + alpha * std::sin(z); }, count);
  Eigen::VectorXd omega(count);
  for (int i = 0; i < count; ++i) {
    omega(i) = mu[static_cast<std::size_t>(i)] / b.length * std::sqrt(b.EA / b.mass_per_length);
  }
  return omega;
}

// The lowest `count` of both families (what natural_frequencies_fe converges to).
inline Eigen::VectorXd in_plane_frequencies_analytic(const PinnedBoom& b, int count) {
  Eigen::VectorXd all(2 * count);
  all << natural_frequencies_analytic(b, count), axial_frequencies_analytic(b, count);
  std::sort(all.data(), all.data() + all.size());
  return all.head(count);
}

// Static deflection w(x) under a uniform transverse load q [N/m] (same sign as w), exact.
// Statically determinate: moments about the pin give the spring force F = qL/2, so w(L) = qL/(2k)
// (a rigid rotation about the pin, w = x w(L)/L), plus the simply supported beam's deflection
// q x (L³ − 2Lx² + x³)/(24EI); the heel rotation is w(L)/L + qL³/(24EI).
inline double static_deflection_analytic(const PinnedBoom& b, double q, double x) {
  require_transverse_tip_wire(b);
  const double L = b.length;
  return x / L * q * L / (2.0 * b.wire_stiffness) +
         q * x * (L * L * L - 2.0 * L * x * x + x * x * x) / (24.0 * b.EI);
}

}  // namespace ffrf::test
