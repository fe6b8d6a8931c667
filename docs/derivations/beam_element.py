#!/usr/bin/env python3
"""Planar Euler-Bernoulli beam element: derivation of the element matrices with sympy.

Run:  /usr/bin/python3 docs/derivations/beam_element.py     (needs python3-sympy)

Shape functions of paper eq. 4 (written there, misprinted, as a 4x3 array; it is the 2x6 matrix
below), element DOFs (u1, v1, phi1, u2, v2, phi2), xi = x/l, mu = rho*A mass per unit length:

    S(xi) = [[1-xi, 0,  0,  xi, 0,  0 ],
             [0,    N1, N2, 0,  N3, N4]]
    N1 = 1 - 3 xi^2 + 2 xi^3,  N2 = l (xi - 2 xi^2 + xi^3),
    N3 = 3 xi^2 - 2 xi^3,      N4 = l (-xi^2 + xi^3).

Derived here, each checked against its textbook closed form (Przemieniecki, Theory of Matrix
Structural Analysis, 1968, ch. 11 and 15; Shabana, Dynamics of Multibody Systems, ch. 6):
  consistent mass      M_e  = int mu S^T S dx
  elastic stiffness    K_e  from  U = 1/2 int (EA u'^2 + EI v''^2) dx
  geometric stiffness  KG_e = P int v'^T v' dx    (P > 0 tension)
  shape integrals      int mu S dx, int mu x S dx, int mu S^T It S dx  (It = [[0,-1],[1,0]])
                       and, with u0 = (x0 + x, 0) for an element starting at x0:
                       s0 = int mu u0, J0 = int mu u0^T u0, d = int mu u0^T S, c = int mu u0^T It S
The script exits non-zero if any assertion fails. See docs/theory.md section 1-2.
"""
import sympy as sp

xi, l, mu, EA, EI, P, x0 = sp.symbols('xi l mu EA EI P x0', positive=True)
x = l * xi                       # local coordinate, dx = l dxi

N1 = 1 - 3*xi**2 + 2*xi**3
N2 = l*(xi - 2*xi**2 + xi**3)
N3 = 3*xi**2 - 2*xi**3
N4 = l*(-xi**2 + xi**3)
Nu = sp.Matrix([[1 - xi, 0, 0, xi, 0, 0]])
Nv = sp.Matrix([[0, N1, N2, 0, N3, N4]])
S = Nu.col_join(Nv)              # 2x6
It = sp.Matrix([[0, -1], [1, 0]])


def integ(expr):
    """int_0^l (.) dx for a matrix polynomial in xi."""
    return sp.simplify((expr * l).applyfunc(lambda e: sp.integrate(sp.expand(e), (xi, 0, 1))))


def d_dx(m):
    return m.diff(xi) / l


def check(name, derived, expected):
    diff = sp.simplify(derived - expected)
    assert diff == sp.zeros(*diff.shape), f"{name}: mismatch\n{diff}"
    print(f"\n{name}  (verified against closed form)")
    sp.pprint(sp.factor(derived) if derived.shape != (1, 1) else derived, wrap_line=False)


# --- sanity: nodal interpolation properties of the Hermite functions -------------------------
for f, vals in ((N1, (1, 0, 0, 0)), (N2, (0, 1, 0, 0)), (N3, (0, 0, 1, 0)), (N4, (0, 0, 0, 1))):
    got = (f.subs(xi, 0), d_dx(sp.Matrix([f]))[0].subs(xi, 0),
           f.subs(xi, 1), d_dx(sp.Matrix([f]))[0].subs(xi, 1))
    assert tuple(sp.simplify(g) for g in got) == vals, (f, got)

# --- consistent mass ---------------------------------------------------------------------------
M = integ(mu * S.T * S)
M_bend = mu*l/420 * sp.Matrix([[156, 22*l, 54, -13*l],
                               [22*l, 4*l**2, 13*l, -3*l**2],
                               [54, 13*l, 156, -22*l],
                               [-13*l, -3*l**2, -22*l, 4*l**2]])
M_ref = sp.zeros(6, 6)
ia, ib = [0, 3], [1, 2, 4, 5]
for i, p in enumerate(ia):
    for j, q in enumerate(ia):
        M_ref[p, q] = mu*l/6 * sp.Matrix([[2, 1], [1, 2]])[i, j]
for i, p in enumerate(ib):
    for j, q in enumerate(ib):
        M_ref[p, q] = M_bend[i, j]
check("consistent mass M_e = int mu S^T S dx", M, M_ref)

# --- stiffness ---------------------------------------------------------------------------------
Bu = d_dx(Nu)
Bv = d_dx(d_dx(Nv))
K = integ(EA * Bu.T * Bu + EI * Bv.T * Bv)
K_bend = EI/l**3 * sp.Matrix([[12, 6*l, -12, 6*l],
                              [6*l, 4*l**2, -6*l, 2*l**2],
                              [-12, -6*l, 12, -6*l],
                              [6*l, 2*l**2, -6*l, 4*l**2]])
K_ref = sp.zeros(6, 6)
for i, p in enumerate(ia):
    for j, q in enumerate(ia):
        K_ref[p, q] = EA/l * sp.Matrix([[1, -1], [-1, 1]])[i, j]
for i, p in enumerate(ib):
    for j, q in enumerate(ib):
        K_ref[p, q] = K_bend[i, j]
check("stiffness K_e = int (EA Nu'^T Nu' + EI Nv''^T Nv'') dx", K, K_ref)

# --- geometric stiffness -----------------------------------------------------------------------
Gv = d_dx(Nv)
KG = integ(P * Gv.T * Gv)
KG_bend = P/(30*l) * sp.Matrix([[36, 3*l, -36, 3*l],
                                [3*l, 4*l**2, -3*l, -l**2],
                                [-36, -3*l, 36, -3*l],
                                [3*l, -l**2, -3*l, 4*l**2]])
KG_ref = sp.zeros(6, 6)
for i, p in enumerate(ib):
    for j, q in enumerate(ib):
        KG_ref[p, q] = KG_bend[i, j]
check("geometric stiffness KG_e = P int v'^T v' dx", KG, KG_ref)

# --- element shape integrals (local x from the element's first node) ---------------------------
Sbar = integ(mu * S)
Sbar_ref = mu*l * sp.Matrix([[sp.Rational(1, 2), 0, 0, sp.Rational(1, 2), 0, 0],
                             [0, sp.Rational(1, 2), l/12, 0, sp.Rational(1, 2), -l/12]])
check("int mu S dx", Sbar, Sbar_ref)

xS = integ(mu * x * S)
xS_ref = mu*l**2 * sp.Matrix([[sp.Rational(1, 6), 0, 0, sp.Rational(1, 3), 0, 0],
                              [0, sp.Rational(3, 20), l/30, 0, sp.Rational(7, 20), -l/20]])
check("int mu x S dx", xS, xS_ref)

Sk = integ(mu * S.T * It * S)
# S^T It S = Nv^T Nu - Nu^T Nv; C[i,j] = int mu Nu_i Nv_j over the four bending functions
C = mu*l * sp.Matrix([[sp.Rational(7, 20), l/20, sp.Rational(3, 20), -l/30],
                      [sp.Rational(3, 20), l/30, sp.Rational(7, 20), -l/20]])
Sk_ref = sp.zeros(6, 6)
for i, p in enumerate(ia):
    for j, q in enumerate(ib):
        Sk_ref[q, p] = C[i, j]
        Sk_ref[p, q] = -C[i, j]
check("skew shape integral int mu S^T It S dx", Sk, Sk_ref)
assert sp.simplify(Sk + Sk.T) == sp.zeros(6, 6)

# --- with the undeformed position u0 = (x0 + x, 0) of an element starting at x0 ----------------
u0 = sp.Matrix([x0 + x, 0])
s0 = integ(mu * u0)
J0 = integ(mu * u0.T * u0)
d = integ(mu * u0.T * S)
c = integ(mu * u0.T * It * S)
check("s0 = int mu u0 dx", s0, sp.Matrix([mu*(l*x0 + l**2/2), 0]))
check("J0 = int mu u0^T u0 dx", J0, sp.Matrix([[mu*(l*x0**2 + x0*l**2 + l**3/3)]]))
check("d = int mu u0^T S dx", d, x0*Sbar[0, :] + xS[0, :])
check("c = int mu u0^T It S dx", c, -(x0*Sbar[1, :] + xS[1, :]))
d_ref = mu*l * sp.Matrix([[x0/2 + l/6, 0, 0, x0/2 + l/3, 0, 0]])
c_ref = -mu*l * sp.Matrix([[0, x0/2 + 3*l/20, x0*l/12 + l**2/30, 0, x0/2 + 7*l/20, -x0*l/12 - l**2/20]])
check("d (explicit)", d, d_ref)
check("c (explicit)", c, c_ref)

# --- rigid-body consistency: total mass and first moment are reproduced by M_e ---------------
rigid_x = sp.Matrix([1, 0, 0, 1, 0, 0])      # uniform axial translation
rigid_y = sp.Matrix([0, 1, 0, 0, 1, 0])      # uniform transverse translation
assert sp.simplify((rigid_x.T * M * rigid_x)[0] - mu*l) == 0
assert sp.simplify((rigid_y.T * M * rigid_y)[0] - mu*l) == 0
rot = sp.Matrix([0, 0, 1, 0, l, 1])          # rigid rotation about node 1: v = x, phi = 1
assert sp.simplify((rot.T * M * rot)[0] - mu*l**3/3) == 0
assert sp.simplify(K * rot) == sp.zeros(6, 1) and sp.simplify(K * rigid_y) == sp.zeros(6, 1)

print("\nall beam-element identities verified")
