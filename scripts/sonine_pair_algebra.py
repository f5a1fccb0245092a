"""Exact averages over one colliding pair of Maxwellians, shared by the generators of the closed forms
(scripts/derive_sonine_cpq.py, scripts/derive_sonine_moments.py).

As in theory/sonine/sonine_quadrature.hpp: the sigma integral of a rotation-invariant integrand is 4 pi times its value at
sigma = z, and given g_z = u the pair splits into independent parts (units theta_k = 1/2, a = theta_k/V,
V = theta_k + theta_i): the tagged v_z = r X + a u with X ~ N(0, 1), r = sqrt((1 - a)/2), |v_perp|^2 = s ~ Exp(1); the
partner's v_iz = v_z - u with its own perpendicular part, c_i^2 = s_i + a (X^2/2 - 2 r X u + (1 - a) u^2),
s_i ~ Exp(1); after the collision v_z' = v_z - beta u. Integrands are polynomials in X, s, s_i, r, u (only even powers of
r survive the X average: r^2 = (1 - a)/2; writing W = r X keeps the partner's 1/(1 - a) out), and
4 pi int_0^inf u phi_V u^(n+1) du / P = 2 a Gamma((n + 2)/2) a^(-(n + 2)/2), P = n_i sigma_ki^2 chi_ki sqrt(2 pi V); the
odd powers of u cancel (checked). Products are taken in sympy's Poly arithmetic (exact and fast).
"""
import sys
import sympy as sp

a, b, u, X, r, s, si = sp.symbols("a beta u X r s s_i", positive=True)
GENS = (X, s, si, r, u, a, b)


def poly(expr):
    return sp.Poly(expr, *GENS, domain="QQ")


def laguerre_of(p, alpha, x):
    """L_p^(alpha)(x) for a Poly x, from the explicit sum (Horner in Poly arithmetic)."""
    coeffs = [(-1) ** j * sp.binomial(p + alpha, p - j) / sp.factorial(j) for j in range(p + 1)]
    out = poly(coeffs[p])
    for j in range(p - 1, -1, -1):
        out = out * x + poly(coeffs[j])
    return out


def pair():
    """(c^2, c'^2, c.c', c_i^2) of the tagged particle before and after, and of the partner, as Polys."""
    vz = poly(r * X + a * u)
    vz1 = vz - poly(b * u)
    ps = poly(s)
    return ps + vz * vz, ps + vz1 * vz1, ps + vz * vz1, poly(si) + poly(a * X**2 / 2 - 2 * a * r * X * u + a * (1 - a) * u**2)


def pair_average(e, label):
    """The pair average of the Poly e with the collision kernel, over beta P: {(power of a, power of beta): Rational}."""
    by_n = {}
    for (i, j, l, m, n, al, be), cf in e.terms():
        if i % 2:
            continue
        assert m % 2 == 0
        w = cf * (sp.factorial2(i - 1) if i else 1) * sp.factorial(j) * sp.factorial(l) / sp.Integer(2) ** (m // 2)
        for t in range(m // 2 + 1):  # (1 - a)^(m/2)
            key = (n, al + t, be)
            by_n[key] = by_n.get(key, 0) + w * sp.binomial(m // 2, t) * (-1) ** t
    out = {}
    for (n, al, be), cf in by_n.items():
        if cf == 0:
            continue
        if n % 2:
            sys.exit(f"{label}: odd power u^{n} does not cancel")
        assert be >= 1
        key = (al + 1 - (n + 2) // 2, be - 1)
        out[key] = out.get(key, 0) + cf * 2 * sp.factorial(n // 2)
    return {k: v for k, v in out.items() if v != 0}
