#!/usr/bin/env python3
"""Closed forms of the tracer-diffusion collision integrals C_pq, p, q < 5 (theory/sonine_cpq_table.cpp).

C_pq = <S_q(c^2) int dsigma Theta(g.sigma)(g.sigma) c.[c S_p(c^2) - c' S_p(c'^2)]> over the Maxwellians of the
tagged species k and its partner i (physics-beyond.md section 3), S_p = L_p^(3/2) (Sonine), c = v/sqrt(2 theta_k),
theta = T/m, c' after the collision v' = v - beta (g.sigma) sigma, beta = mu_ik (1 + eps); and (sources 2, 3) the
same with the partner's scalar Sonine weight S_r^(1/2)(c_i^2) inside the average, so that a partner with
f_i = f_M,i[1 + a_i2 S_2 + a_i3 S_3] gives C_pq + a_i2 C_pq^(2) + a_i3 C_pq^(3). As in
theory/sonine_quadrature.hpp: the sigma integral of a rotation-invariant integrand is 4 pi times its value at
sigma = z, and given g_z = u the pair splits into independent parts (units theta_k = 1/2, a = theta_k/V,
V = theta_k + theta_i): v_z = r X + a u with X ~ N(0, 1), r = sqrt((1 - a)/2), |v_perp|^2 = s ~ Exp(1); the
partner's v_iz = v_z - u and its own perpendicular part give c_i^2 = s_i + a (X^2/2 - 2 r X u + (1 - a) u^2),
s_i ~ Exp(1). The integrand is a polynomial in X, s, s_i, r, u (only even powers of r survive the X average:
r^2 = (1 - a)/2), and int_0^inf u^(n+1) phi_V(u) du is a Gamma function. Every C_pq is beta P times a polynomial in
a, 1/a (down to a^-p) and beta with rational coefficients,
P = n_i sigma_ki^2 chi_ki sqrt(2 pi V) (the odd powers of u cancel: checked). p, q < 2 are the closed forms of
theory/sonine2_diffusion.cpp. The products are taken in sympy's Poly arithmetic (exact, 40 s in all).

Writes the C++ table to stdout (about 45 s, needs only sympy):
    python3 scripts/derive_sonine_cpq.py > theory/sonine_cpq_table.cpp
tests/theory/test_sonine_modes.cpp checks the table, all three sources, against an independent quadrature.
"""
import sys
import sympy as sp

from generated_table import print_table

MODES = 5
SOURCES = [0, 2, 3]  # Maxwellian partner; its a_2; its a_3
a, b, u, X, r, s, si = sp.symbols("a beta u X r s s_i", positive=True)


GENS = (X, s, si, r, u, a, b)


def poly(expr):
    return sp.Poly(expr, *GENS, domain="QQ")


def laguerre_of(p, alpha, x):
    """L_p^(alpha)(x) for a Poly x, from the explicit sum (Horner in Poly arithmetic: fast exact products)."""
    coeffs = [(-1) ** j * sp.binomial(p + alpha, p - j) / sp.factorial(j) for j in range(p + 1)]
    out = poly(coeffs[p])
    for j in range(p - 1, -1, -1):
        out = out * x + poly(coeffs[j])
    return out


def cpq(p, q, source=0):
    """C_pq/(beta P) as {(power of a, power of beta): Rational}."""
    # W = r X with r = sqrt((1 - a)/2): the partner's a (W - (1 - a) u)^2/(1 - a) = a X^2/2 - 2 a r X u + a (1 - a) u^2
    # stays polynomial (no 1/(1 - a) to cancel).
    vz = poly(r * X + a * u)
    vz1 = vz - poly(b * u)
    ps, psi = poly(s), poly(si)
    c2, c2p, cc = ps + vz * vz, ps + vz1 * vz1, ps + vz * vz1
    ci2 = psi + poly(a * X**2 / 2 - 2 * a * r * X * u + a * (1 - a) * u**2)
    weight = laguerre_of(source, sp.Rational(1, 2), ci2) if source else poly(1)
    e = weight * laguerre_of(q, sp.Rational(3, 2), c2) * (c2 * laguerre_of(p, sp.Rational(3, 2), c2) - cc * laguerre_of(p, sp.Rational(3, 2), c2p))
    # E over X ~ N(0, 1), s, s_i ~ Exp(1); r^2 = (1 - a)/2 (every r comes with one X: odd powers vanish with the odd
    # moments of X); then 4 pi int_0^inf u phi_V u^n du / P = 2 a Gamma((n + 2)/2) a^(-(n + 2)/2) with V = 1/(2a).
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
            sys.exit(f"C_{p}{q} (source {source}): odd power u^{n} does not cancel")
        assert be >= 1
        key = (al + 1 - (n + 2) // 2, be - 1)
        out[key] = out.get(key, 0) + cf * 2 * sp.factorial(n // 2)
    return {k: v for k, v in out.items() if v != 0}


def main():
    rows = []
    for src, rs in enumerate(SOURCES):
        for p in range(MODES):
            for q in range(MODES):
                for (ia, ib), cf in sorted(cpq(p, q, rs).items()):  # a^-p is the lowest power
                    if not cf.is_Rational:
                        sys.exit(f"C_{p}{q} (source {rs}): coefficient {cf} is not rational")
                    rows.append(f"    {{{src}, {p}, {q}, {ia}, {ib}, {sp.Rational(cf).p}.0 / {sp.Rational(cf).q}.0}},")
    print_table("derive_sonine_cpq.py", "C_pq / (beta P) = sum of coefficient * a^ia * beta^ib over the rows of (source, p, q)",
                "sonine_cpq_table.hpp", "SonineCpqTerm", "sonine_cpq_term_count", "sonine_cpq_terms", rows)

if __name__ == "__main__":
    main()
