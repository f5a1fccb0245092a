#!/usr/bin/env python3
"""Exact collision moments of the second Sonine approximation (theory/sonine/sonine_second_order.cpp).

One species of inelastic hard spheres, d = 3, constant restitution alpha, reduced units of Brilliantov &
Poschel: f = phi_M (1 + a2 S2(c^2) + a3 S3(c^2)), phi_M = pi^(-3/2) exp(-c^2), and
  mu_p = -(1/2) int dc1 dc2 phi_M phi_M W int dsigma Theta(-g.sigma) |g.sigma| Delta(c1^p + c2^p),
W linear in a2, a3. With sigma = z (times 4 pi, rotation) and Theta -> 1/2 (reflection of z):
  mu_p = -pi int phi_M phi_M W |g_z| Delta(c1^p + c2^p),
in centre-of-mass C = (c1 + c2)/2 and relative g = c1 - c2 velocities (weight exp(-2C^2 - g^2/2)); the
integrand is a polynomial, integrated monomial by monomial. Prints the coefficients of mu_2, mu_4, mu_6
divided by sqrt(2 pi), the exact second-Sonine (linear scheme) a2, a3 at a few alpha, and needs only sympy
(about 20 s). tests/theory/test_sonine_second_order.cpp checks the C++ transcription by quadrature.
"""
import sympy as sp

al, a2, a3 = sp.symbols("alpha a2 a3")
Cx, Cy, Cz, gx, gy, gz = sp.symbols("Cx Cy Cz gx gy gz", real=True)


def S2(x):
    return x**2 / 2 - sp.Rational(5, 2) * x + sp.Rational(15, 8)


def S3(x):
    return -x**3 / 6 + sp.Rational(7, 4) * x**2 - sp.Rational(35, 8) * x + sp.Rational(35, 16)


def sq(v):
    return (v.T * v)[0]


def gauss(n, a, absolute=False):  # int x^n exp(-a x^2) dx, or int |x| x^n exp(-a x^2) dx
    if n % 2:
        return 0
    k = n + 2 if absolute else n + 1
    return sp.gamma(sp.Rational(k, 2)) * a ** sp.Rational(-k, 2)


C, g = sp.Matrix([Cx, Cy, Cz]), sp.Matrix([gx, gy, gz])
g_post = sp.Matrix([gx, gy, -al * gz])  # sigma = z: g' = g - (1 + alpha)(g.z)z
x1, x2 = sq(C + g / 2), sq(C - g / 2)
y1, y2 = sq(C + g_post / 2), sq(C - g_post / 2)
W = 1 + a2 * (S2(x1) + S2(x2)) + a3 * (S3(x1) + S3(x2))
half = sp.Rational(1, 2)
mu = {}
for p in (2, 4, 6):
    k = p // 2
    poly = sp.Poly(sp.expand(W * (y1**k + y2**k - x1**k - x2**k)), Cx, Cy, Cz, gx, gy, gz)
    total = 0
    for (ex, ey, ez, hx, hy, hz), coef in poly.terms():
        total += coef * gauss(ex, 2) * gauss(ey, 2) * gauss(ez, 2) * gauss(hx, half) * gauss(hy, half) * gauss(hz, half, True)
    mu[p] = sp.expand(sp.simplify(-sp.pi * total / sp.pi**3 / sp.sqrt(2 * sp.pi)))
    for name, term in (("1", mu[p].subs({a2: 0, a3: 0})), ("a2", mu[p].coeff(a2)), ("a3", mu[p].coeff(a3))):
        print(f"mu_{p}/sqrt(2 pi), coefficient of {name}: {sp.factor(term)}")

# HCS: mu_4 = 5 mu_2 (1 + a2), mu_6 = (105/4) mu_2 (1 + 3 a2 - a3), linearised in a2, a3.
eq4 = mu[4] - 5 * mu[2] * (1 + a2)
eq6 = mu[6] - sp.Rational(105, 4) * mu[2] * (1 + 3 * a2 - a3)
drop = {a2**2: 0, a2 * a3: 0, a3**2: 0}
lin = [sp.expand(e).subs(drop) for e in (eq4, eq6)]
for alpha in (sp.Rational(3, 10), sp.Rational(1, 2), sp.Rational(3, 5), sp.Rational(4, 5), sp.Rational(9, 10)):
    s = sp.solve([e.subs(al, alpha) for e in lin], [a2, a3])
    print(f"alpha = {alpha}: a2[2] = {sp.N(s[a2], 10)}, a3[2] = {sp.N(s[a3], 10)}")
