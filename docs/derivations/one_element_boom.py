#!/usr/bin/env python3
"""The paper's one-element elastic boom (Park, Cha & Lee 2009, section 4), derived from scratch.

Run:  /usr/bin/python3 docs/derivations/one_element_boom.py    (needs python3-sympy, numpy, scipy)

Boom frame at R = (x, y), angle theta, root node B clamped to the frame, free coordinates
q_f = (u2, v2, phi2) of the tip node (paper eq. 26). With xi = s/l in [0, 1]:
    u0(xi) = (xi l, 0)                                   undeformed position, body frame
    S(xi)  = [[xi, 0, 0], [0, 3xi^2 - 2xi^3, l(xi^3 - xi^2)]]      paper eq. 26.a
    r(xi)  = R + A(theta) (u0 + S q_f),   A = [[cos, -sin], [sin, cos]]
uniform mass m_B over the length l (rho dx = m_B dxi). Generalized coordinates
q = (x, y, theta, q_f1, q_f2, q_f3) (paper eq. 23.c).

Derived from the definitions only:
    T   = 1/2 int rho |dr/dt|^2 dx                 -> M = d2T/dqdot2          (paper eq. 18-19)
    Q_v = -Mdot qdot + dT/dq                        with  M qddot = ... + Q_v  (paper eq. 20.c, 21)
    Q_g = int rho L^T (0, -g) dx   (virtual work)   and  -dV/dq, V = g int rho y dx
    Q_F = L(xi = 1)^T F            (point force F, global frame, at the tip; paper eq. 13, 38)
and re-assembled from the general FFRF blocks of docs/theory.md section 2 (inertia invariants),
then compared term by term with the printed eqs. 28.c-28.d, 38-39 and 42 (the misprints found
are listed in docs/theory.md section 4 and printed below), and cross-checked numerically:
    (a) M against T by Gauss quadrature (velocities by complex-step differentiation of r), and
        against differences of that T in qdot (exact: T is quadratic in qdot);
    (b) Q_v against finite differences of the quadrature T (Lagrange's equations), and by
        integrating free flights (DOP853, tight tolerances): energy, linear and angular momentum;
    (c) Q_g against finite differences of V = g int rho y dx (quadrature).
Finally it writes tests/multibody/one_element_reference.hpp (C++/Eigen, via sympy cxxcode) — the
independent reference for the C++ floating-frame body. Do not edit that header by hand.
"""
import os
import sys

import numpy as np
import sympy as sp
from sympy.printing.cxx import cxxcode

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
HEADER = os.path.join(ROOT, "tests", "coupling", "one_element_reference.hpp")

# ----------------------------------------------------------------------------------------------
# 1. symbolic derivation
# ----------------------------------------------------------------------------------------------
mB, l, g = sp.symbols("m_B l g", positive=True)
xi = sp.symbols("xi", real=True)
x, y, th, q1, q2, q3 = sp.symbols("x y theta q_f1 q_f2 q_f3", real=True)
xd, yd, thd, q1d, q2d, q3d = sp.symbols("xdot ydot thetadot qdot_f1 qdot_f2 qdot_f3", real=True)
Fx, Fy = sp.symbols("F_x F_y", real=True)
q = sp.Matrix([x, y, th, q1, q2, q3])
qd = sp.Matrix([xd, yd, thd, q1d, q2d, q3d])
qf = sp.Matrix([q1, q2, q3])
s, c = sp.sin(th), sp.cos(th)

A = sp.Matrix([[c, -s], [s, c]])
It = sp.Matrix([[0, -1], [1, 0]])
Sxi = sp.Matrix([[xi, 0, 0], [0, 3*xi**2 - 2*xi**3, l*(xi**3 - xi**2)]])
u0 = sp.Matrix([xi*l, 0])
r = sp.Matrix([x, y]) + A * (u0 + Sxi * qf)

L = r.jacobian(q)                       # velocity transformation matrix, paper eq. 10
rdot = L * qd


def integ(e):
    """int rho (.) dx = m_B int_0^1 (.) dxi, elementwise."""
    f = lambda t: sp.integrate(sp.expand(t), (xi, 0, 1))
    return (mB * e.applyfunc(f)) if isinstance(e, sp.MatrixBase) else mB * f(e)


T = sp.simplify(integ((rdot.T * rdot)[0]) / 2)
M = sp.hessian(T, qd).applyfunc(sp.simplify)
assert sp.simplify(M - integ(L.T * L)) == sp.zeros(6, 6)          # paper eq. 19.b
assert sp.expand(T - (qd.T * M * qd)[0] / 2) == 0

Mdot = sp.zeros(6, 6)
for k in range(6):
    Mdot += M.diff(q[k]) * qd[k]
Qv = (-Mdot * qd + sp.Matrix([T.diff(qk) for qk in q])).applyfunc(
    lambda e: sp.collect(sp.expand(sp.simplify(e)), [s, c]))
# the same thing by d'Alembert: Q_v = -int rho L^T (dL/dt) qdot
Ldot = sp.zeros(2, 6)
for k in range(6):
    Ldot += L.diff(q[k]) * qd[k]
assert sp.simplify(Qv + integ(L.T * Ldot * qd)) == sp.zeros(6, 1)

Qg = integ(L.T * sp.Matrix([0, -g])).applyfunc(sp.simplify)       # virtual work
V = g * integ(r[1])
assert sp.simplify(Qg + sp.Matrix([V.diff(qk) for qk in q])) == sp.zeros(6, 1)
assert sp.simplify(Qg + g * M[1, :].T) == sp.zeros(6, 1)           # Q_g = -g * (row y of M)

# the general FFRF blocks of docs/theory.md section 2, written with the inertia invariants
# (Phi = I): they must reproduce M and Q_v derived above from T directly
m_ = integ(sp.Integer(1)); s0_ = integ(u0); J0_ = integ((u0.T*u0)[0])
Sb_ = integ(Sxi); d_ = integ(u0.T*Sxi); c_ = integ(u0.T*It*Sxi)
Mff_ = integ(Sxi.T*Sxi); Sk_ = integ(Sxi.T*It*Sxi)
qfd = sp.Matrix([q1d, q2d, q3d])
Minv = sp.zeros(6, 6)
Minv[0:2, 0:2] = m_*sp.eye(2)
Minv[0:2, 2] = A*It*(s0_ + Sb_*qf)
Minv[0:2, 3:6] = A*Sb_
Minv[2, 2] = J0_ + 2*(d_*qf)[0] + (qf.T*Mff_*qf)[0]
Minv[2, 3:6] = -(c_ + qf.T*Sk_)
Minv[3:6, 3:6] = Mff_
for i in range(6):
    for j in range(i):
        Minv[i, j] = Minv[j, i]
assert sp.simplify(Minv - M) == sp.zeros(6, 6)
Qinv = sp.zeros(6, 1)
Qinv[0:2, 0] = thd**2*A*(s0_ + Sb_*qf) - 2*thd*A*It*Sb_*qfd
Qinv[2, 0] = -2*thd*((d_ + qf.T*Mff_)*qfd)[0]
Qinv[3:6, 0] = thd**2*(d_.T + Mff_*qf) - 2*thd*Sk_*qfd
assert sp.simplify(Qinv - Qv) == sp.zeros(6, 1)
assert sp.simplify(Qg - sp.Matrix([0, -m_*g, -g*(A*It*(s0_ + Sb_*qf))[1], *(-g*(A*Sb_)[1, :])])) \
    == sp.zeros(6, 1)
print("general FFRF blocks in terms of the invariants (theory.md section 2): reproduce M, Q_v, Q_g")

Ltip = L.subs(xi, 1)
QF = (Ltip.T * sp.Matrix([Fx, Fy])).applyfunc(sp.simplify)


def show(title, m):
    print(f"\n{title}")
    sp.pprint(m, wrap_line=False)


show("mass matrix M_B over (x, y, theta, q_f1, q_f2, q_f3)", M.applyfunc(sp.factor))
show("quadratic velocity vector Q_v", Qv)
show("gravity Q_g", Qg)
show("tip point force Q_F = L(1)^T F", QF)

# ----------------------------------------------------------------------------------------------
# 2. term-by-term comparison with the printed equations
# ----------------------------------------------------------------------------------------------
R = sp.Rational
P = {}   # printed entries (as printed, including misprints)
P["M"] = {
    (0, 0): mB, (0, 1): 0, (1, 1): mB,
    (0, 2): -mB/2*(l + q1)*s - mB/12*(6*q2 - l*q3)*c,
    (0, 3): mB/2*c, (0, 4): mB/2*s, (0, 5): mB*l/12*s,
    (1, 2): mB/2*(l + q1)*c - mB/12*(6*q2 - l*q3)*s,
    (1, 3): mB/2*s, (1, 4): mB/2*c, (1, 5): -mB*l/12*c,
    (2, 2): mB*(l**2/3 + 2*l*q1/3 + q1**2/3 + R(13, 35)*q2**2 - R(11, 105)*l*q2*q3
                + R(1, 105)*l**2*q3**2),
    (2, 3): mB/20*(-7*q2 + l*q3), (2, 4): 7*mB/20*(l + q1), (2, 5): -mB*l/20*(l + q1),
    (3, 3): mB/3, (3, 4): 0, (3, 5): 0,
    (4, 4): R(13, 35)*mB, (4, 5): -R(11, 210)*mB*l, (5, 5): R(1, 105)*mB*l**2,
}
QgB30 = -mB*g*(R(1, 2)*(l + q1)*c - (R(1, 2)*q2 - R(1, 8)*l*q3)*s)
P["Qg"] = [0, -mB*g, QgB30, -R(1, 2)*mB*g*s, -R(1, 2)*mB*g*c, R(1, 8)*mB*g*l*c]
Q31 = -(l + q1)*s - q2*c
Q32 = (l + q1)*c - q2*s
# eq. 38 wire matrix as printed: five rows for a six-row vector
P["G"] = [[1, 0], [0, 1], [Q31*c, Q32*s], [-s, c], [0, 0]]
P["Qv"] = [
    mB*thd**2/2*(l + q1)*c - mB*thd**2/12*(6*q2 - l*q3)*s + mB*thd*q1d*s
    + mB*thd/6*(6*q2d - l*q3d)*c,
    mB*thd**2/2*(l + q1)*s + mB*thd**2/12*(6*q2 - l*q3)*c - mB*thd*q1d*c
    + mB*thd/6*(6*q2d - l*q3d)*s,
    -2*thd*mB*(q1*q1d/3 + R(13, 35)*q2*q2d - R(11, 210)*l*q3*q2d - R(11, 210)*l*q2*q3d
               + R(1, 105)*l**2*q3*q3d + l/3*q1d),
    R(1, 3)*thd**2*mB*(q1 + l) + R(7, 10)*thd*mB*q2d - R(1, 10)*thd*mB*l*q3d,
    R(13, 35)*thd**2*mB*q2 - R(11, 210)*thd**2*mB*l*q3 - R(7, 10)*thd*mB*q1d,
    -R(11, 210)*thd**2*mB*l*q2 + R(1, 105)*thd**2*mB*l**2*q3 + R(1, 10)*thd*mB*l*q1d,
]
names = ["x", "y", "theta", "q_f1", "q_f2", "q_f3"]
misprints = []


def cmp(label, printed, derived):
    ok = sp.simplify(sp.expand_trig(printed - derived)) == 0
    print(f"  {label:32s} {'ok' if ok else 'MISPRINT'}")
    if not ok:
        misprints.append((label, printed, derived))
    return ok


print("\n--- comparison with the printed equations ---")
print("eq. 28.c-28.d mass matrix (upper triangle m_ij, 1-based):")
for (i, j), v in sorted(P["M"].items()):
    cmp(f"m{i+1}{j+1}", v, M[i, j])
print("eq. 38-39 gravity part of Q_e,B:")
for i in range(6):
    cmp(f"Q_g[{names[i]}]" + (" (Q_e,B30)" if i == 2 else ""), P["Qg"][i], Qg[i])
print("eq. 39 wire-force coefficients:")
cmp("Q_e,B31", Q31, Ltip[:, 2][0])
cmp("Q_e,B32", Q32, Ltip[:, 2][1])
print("eq. 38 wire-force matrix L(1)^T (printed with 5 rows; correct one has 6):")
G = Ltip.T
for i, row in enumerate(P["G"]):
    for k in range(6):
        if all(sp.simplify(row[j] - G[k, j]) == 0 for j in range(2)):
            print(f"  printed row {i+1} {row} = correct row {k+1} ({names[k]})")
            break
    else:
        print(f"  printed row {i+1} {row}: matches no row of L(1)^T  MISPRINT")
        misprints.append((f"eq. 38 wire matrix row {i+1}", sp.Matrix([row]), None))
for k in range(6):
    if not any(all(sp.simplify(row[j] - G[k, j]) == 0 for j in range(2)) for row in P["G"]):
        print(f"  correct row {k+1} ({names[k]}) {list(G[k, :])} is missing  MISPRINT")
        misprints.append((f"eq. 38 wire matrix, missing row {names[k]}", None, G[k, :]))
print("eq. 42 quadratic velocity vector:")
for i in range(6):
    cmp(f"Q_v[{names[i]}]", P["Qv"][i], Qv[i])
print("\nmisprints found in eqs. 28, 38, 39, 42:")
for label, pr, de in misprints:
    pr = "(absent)" if pr is None else sp.factor(pr)
    de = "(no such row)" if de is None else sp.factor(de)
    print(f"  {label}:\n      printed {pr}\n      correct {de}")

# ----------------------------------------------------------------------------------------------
# 3. independent numerical cross-checks
# ----------------------------------------------------------------------------------------------
from scipy.integrate import solve_ivp   # noqa: E402

vals = {mB: 3.7, l: 2.3, g: 9.81}
EA_, EI_ = 4.0e3, 60.0                      # only for the flights (clamped tip stiffness)
Kf = np.array([[EA_/2.3, 0, 0], [0, 12*EI_/2.3**3, -6*EI_/2.3**2], [0, -6*EI_/2.3**2, 4*EI_/2.3]])
mB_, l_, g_ = vals[mB], vals[l], vals[g]
gx, gw = np.polynomial.legendre.leggauss(8)
gx, gw = 0.5*(gx + 1), 0.5*gw               # on [0, 1]: exact to degree 15

r_num = sp.lambdify((xi, q), r.subs(vals), "numpy")
M_num = sp.lambdify((q,), M.subs(vals), "numpy")
Qv_num = sp.lambdify((q, qd), Qv.subs(vals), "numpy")
Qg_num = sp.lambdify((q,), Qg.subs(vals), "numpy")
QF_num = sp.lambdify((q, Fx, Fy), QF.subs(vals), "numpy")


def pos(xv, qv):
    return np.asarray(r_num(xv, list(qv)), dtype=float).reshape(2)


def vel(xv, qv, qdv, h=1e-30):
    """rdot = (dr/dq) qdot by the complex-step derivative of the position (exact to rounding)."""
    z = np.asarray(r_num(xv, list(np.asarray(qv) + 1j*h*np.asarray(qdv))), dtype=complex)
    return z.reshape(2).imag / h


def T_quad(qv, qdv):
    """Kinetic energy 1/2 int rho |rdot|^2 dx by Gauss quadrature."""
    return sum(w * mB_ * vel(xv, qv, qdv) @ vel(xv, qv, qdv) / 2 for xv, w in zip(gx, gw))


def d1(f, x0, e, h=1e-3):
    """4th-order central difference of f at x0 along e."""
    return (-f(x0 + 2*h*e) + 8*f(x0 + h*e) - 8*f(x0 - h*e) + f(x0 - 2*h*e)) / (12*h)


def V_quad(qv):
    return sum(w * mB_ * g_ * pos(xv, qv)[1] for xv, w in zip(gx, gw))


rng = np.random.default_rng(20090615)
worst = {"a_T": 0, "a_M": 0, "b_Qv": 0, "c_Qg": 0, "F": 0}
for trial in range(10):
    qv = np.concatenate([rng.normal(size=2), rng.uniform(-np.pi, np.pi, 1), 0.2*rng.normal(size=3)])
    qdv = rng.normal(size=6)
    Mq = np.array(M_num(qv), dtype=float)
    # (a) T = 1/2 qdot^T M qdot, and M from mixed differences of T in qdot (T is quadratic)
    Tq = T_quad(qv, qdv)
    worst["a_T"] = max(worst["a_T"], abs(Tq - qdv @ Mq @ qdv / 2) / Tq)
    E = np.eye(6)
    Mfd = np.array([[(T_quad(qv, E[i] + E[j]) - T_quad(qv, E[i] - E[j])) / 2 for j in range(6)]
                    for i in range(6)])
    worst["a_M"] = max(worst["a_M"], np.abs(Mfd - Mq).max() / np.abs(Mq).max())
    # (b) Lagrange: Q_v = dT/dq - Mdot qdot, both by central differences of quadrature quantities
    dTdq = np.array([d1(lambda z: T_quad(z, qdv), qv, E[k]) for k in range(6)])
    # Mdot qdot = d/dt (dT/dqdot) at fixed qdot, with dT/dqdot itself by differences of T
    pT = lambda z: np.array([(T_quad(z, qdv + E[i]) - T_quad(z, qdv - E[i])) / 2 for i in range(6)])
    Qv_fd = dTdq - d1(pT, qv, qdv)
    Qv_sym = np.array(Qv_num(qv, qdv), dtype=float).ravel()
    worst["b_Qv"] = max(worst["b_Qv"], np.abs(Qv_fd - Qv_sym).max() / np.abs(Qv_sym).max())
    # (c) gravity from the potential V = g int rho y dx
    Qg_fd = -np.array([d1(V_quad, qv, E[k]) for k in range(6)])
    Qg_sym = np.array(Qg_num(qv), dtype=float).ravel()
    worst["c_Qg"] = max(worst["c_Qg"], np.abs(Qg_fd - Qg_sym).max() / np.abs(Qg_sym).max())
    # tip force: virtual work F . delta r_tip
    F = rng.normal(size=2)
    QF_fd = np.array([F @ vel(1.0, qv, E[k]) for k in range(6)])
    QF_sym = np.array(QF_num(qv, F[0], F[1]), dtype=float).ravel()
    worst["F"] = max(worst["F"], np.abs(QF_fd - QF_sym).max() / np.abs(QF_sym).max())
print("\n--- numerical cross-checks (10 random states, worst relative error) ---")
for k, v in worst.items():
    print(f"  {k:5s} {v:.2e}")
    assert v < 1e-9, k


def rhs(t, z, grav):
    qv, qdv = z[:6], z[6:]
    f = np.array(Qv_num(qv, qdv), dtype=float).ravel()
    f[3:] -= Kf @ qv[3:]
    if grav:
        f += np.array(Qg_num(qv), dtype=float).ravel()
    return np.concatenate([qdv, np.linalg.solve(np.array(M_num(qv), float), f)])


def invariants(z):
    qv, qdv = z[:6], z[6:]
    Mq = np.array(M_num(qv), float)
    energy = qdv @ Mq @ qdv / 2 + qv[3:] @ Kf @ qv[3:] / 2
    p, H = np.zeros(2), 0.0          # momentum and angular momentum about O by quadrature
    for xv, w in zip(gx, gw):
        rp, v = pos(xv, qv), vel(xv, qv, qdv)
        p += w * mB_ * v
        H += w * mB_ * (rp[0]*v[1] - rp[1]*v[0])
    return energy, p, H


z0 = np.concatenate([[0.3, -0.2, 0.4, 0.05, -0.1, 0.08], [0.5, 0.7, 2.5, -0.3, 1.0, -0.6]])
for grav in (False, True):
    sol = solve_ivp(rhs, (0, 3.0), z0, method="DOP853", rtol=1e-12, atol=1e-12, args=(grav,))
    e0, p0, H0 = invariants(z0)
    e1, p1, H1 = invariants(sol.y[:, -1])
    if grav:
        e0 += V_quad(z0[:6]); e1 += V_quad(sol.y[:6, -1])
        print(f"  flight with gravity, 3 s: |dE|/E = {abs(e1-e0)/abs(e0):.1e}, "
              f"|dp_x| = {abs(p1[0]-p0[0]):.1e}")
        assert abs(e1 - e0) / abs(e0) < 1e-8 and abs(p1[0] - p0[0]) < 1e-7
    else:
        print(f"  free flight, 3 s ({sol.t.size} steps): |dE|/E = {abs(e1-e0)/e0:.1e}, "
              f"|dp| = {np.abs(p1-p0).max():.1e}, |dH| = {abs(H1-H0):.1e}  (|H| = {abs(H0):.2f})")
        assert abs(e1 - e0) / e0 < 1e-8 and np.abs(p1 - p0).max() < 1e-7 and abs(H1 - H0) < 1e-7

# ----------------------------------------------------------------------------------------------
# 4. C++ reference header
# ----------------------------------------------------------------------------------------------
cpp_sym = {x: "q(0)", y: "q(1)"}
scalars = [(th, "th", "q(2)"), (q1, "qf1", "q(3)"), (q2, "qf2", "q(4)"), (q3, "qf3", "q(5)"),
           (thd, "thd", "qdot(2)"), (q1d, "qf1d", "qdot(3)"), (q2d, "qf2d", "qdot(4)"),
           (q3d, "qf3d", "qdot(5)"), (xd, "xd", "qdot(0)"), (yd, "yd", "qdot(1)"),
           (Fx, "Fx", "F(0)"), (Fy, "Fy", "F(1)")]
rename = {mB: sp.Symbol("mB"), l: sp.Symbol("l"), g: sp.Symbol("g")}
for sym, name, _ in scalars:
    rename[sym] = sp.Symbol(name)


def cpp_function(signature, rettype, expr, doc):
    expr = expr.subs(rename)
    used = expr.free_symbols
    lines = [f"// {d}" for d in doc] + [f"inline {rettype} {signature} {{"]
    for sym, name, src in scalars:
        if sp.Symbol(name) in used:
            lines.append(f"  const double {name} = {src};")
    subexprs, (red,) = sp.cse(expr, symbols=sp.numbered_symbols("t"), optimizations="basic")
    for sym, e in subexprs:
        lines.append(f"  const double {sym} = {cxxcode(e, standard='C++17')};")
    lines.append(f"  {rettype} out;")
    for i in range(red.rows):
        for j in range(red.cols):
            idx = f"{i}, {j}" if red.cols > 1 else f"{i}"
            v = red[i, j]
            code = "0.0" if v == 0 else cxxcode(v, standard='C++17')
            lines.append(f"  out({idx}) = {code};")
    lines += ["  return out;", "}", ""]
    return "\n".join(lines)


header = [
    "// GENERATED by docs/derivations/one_element_boom.py — DO NOT EDIT BY HAND.",
    "// Regenerate with: /usr/bin/python3 docs/derivations/one_element_boom.py",
    "//",
    "// Independent symbolic reference for the paper's one-element elastic boom (Park, Cha & Lee",
    "// 2009, section 4): floating frame at R = (x, y), angle theta, root clamped, free tip DOFs",
    "// q_f = (u2, v2, phi2), shape matrix of paper eq. 26.a, u0 = (xi l, 0), uniform mass mB over l.",
    "// q = (x, y, theta, q_f1, q_f2, q_f3). Equation of motion M qddot = Q_v + Q_g + Q_F - K q + ...",
    "// Derived from T = 1/2 int rho |rdot|^2 dx (no use of the paper's printed formulas, which",
    "// contain misprints: see docs/theory.md section 4).",
    "#pragma once",
    "",
    "#include <cmath>",
    "",
    "#include <Eigen/Dense>",
    "",
    "namespace ffrf::test {",
    "",
    cpp_function("one_element_mass(\n    double mB, double l, const Eigen::Matrix<double, 6, 1>& q)",
                 "Eigen::Matrix<double, 6, 6>", M,
                 ["Mass matrix M = int rho L^T L dx (paper eq. 19, 28.c-28.d; m15 corrected)."]),
    cpp_function("one_element_quadratic_velocity(\n    double mB, double l, const Eigen::Matrix<double, 6, 1>& q,\n"
                 "    const Eigen::Matrix<double, 6, 1>& qdot)",
                 "Eigen::Matrix<double, 6, 1>", Qv,
                 ["Quadratic velocity vector Q_v = -Mdot qdot + (dT/dq)^T, on the right-hand side",
                  "(paper eq. 20.c, 21, 42)."]),
    cpp_function("one_element_gravity(\n    double mB, double l, double g, const Eigen::Matrix<double, 6, 1>& q)",
                 "Eigen::Matrix<double, 6, 1>", Qg,
                 ["Generalized gravity force, g along -y (paper eq. 38-39 first term; 1/8 -> 1/12)."]),
    cpp_function("one_element_tip_force(\n    double l, const Eigen::Matrix<double, 6, 1>& q, const Eigen::Vector2d& F)",
                 "Eigen::Matrix<double, 6, 1>", QF,
                 ["Generalized force L(xi=1)^T F of a point force F (global frame) at the tip",
                  "(paper eq. 13; the wire-force matrix of eq. 38, corrected)."]),
    "}  // namespace ffrf::test",
    "",
]
text = "\n".join(header)
os.makedirs(os.path.dirname(HEADER), exist_ok=True)
with open(HEADER, "w", encoding="utf-8") as fh:
    fh.write(text)
print(f"\nwrote {os.path.relpath(HEADER, ROOT)}")
if "--sample" in sys.argv:   # one state, for a C++ round-trip check: q, qdot, F, M, Q_v, Q_g, Q_F
    qs = np.array([0.3, -1.2, 0.7, 0.05, -0.11, 0.09]); qds = np.array([0.4, -0.3, 1.7, 0.2, -0.8, 0.5])
    Fs = np.array([1.3e3, -2.1e3])
    out = [qs, qds, Fs, np.array(M_num(qs), float).ravel(), np.array(Qv_num(qs, qds), float).ravel(),
           np.array(Qg_num(qs), float).ravel(), np.array(QF_num(qs, *Fs), float).ravel()]
    with open(sys.argv[sys.argv.index("--sample") + 1], "w") as fh:
        fh.write(f"{mB_!r} {l_!r} {g_!r}\n" + "\n".join(" ".join(repr(float(v)) for v in a) for a in out) + "\n")
print("\nall one-element boom checks passed")
