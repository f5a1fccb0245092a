#!/usr/bin/env python3
"""Closed forms of the scalar Sonine collision moments H(p; q, r), p = 1..3 (theory/sonine_moment_table.cpp).

The kinetic level's temperatures with a_2 and a_3 per species (theory/sonine_moment_cooling.hpp): species k's
distribution is f_k = f_M,k [1 + a_k2 S_2(c^2) + a_k3 S_3(c^2)], S_p = L_p^(1/2) (the scalar Sonine polynomials),
c = v/sqrt(2 theta_k), theta = T/m. The collisional rate of <c^(2p)>_k at fixed theta_k from collisions with
species i, linear in the a's (products a a dropped, as Garzo-Dufty/MG do at first Sonine), is

    R_p = P [H(p; 0, 0) + sum_q a_kq H(p; q, 0) + sum_r a_ir H(p; 0, r)],
    H(p; q, r) = <S_q(c_k^2) S_r(c_i^2) int dsigma Theta(g.sigma)(g.sigma) [c_k'^(2p) - c_k^(2p)]>

over the Maxwellians of k and i, P = n_i sigma_ki^2 chi_ki sqrt(2 pi V), V = theta_k + theta_i, c' after the
collision v_k' = v_k - beta (g.sigma) sigma, beta = mu_ik (1 + eps). As in scripts/derive_sonine_cpq.py: the sigma
integral is 4 pi times the integrand at sigma = z; given g_z = u the pair splits into independent parts (units
theta_k = 1/2, a = theta_k/V): v_kz = W + a u, W ~ N(0, (1 - a)/2), |v_k,perp|^2 = s ~ Exp(1); the partner's
v_iz = W - (1 - a) u and c_i^2 = s_i + a (W - (1 - a) u)^2/(1 - a), s_i ~ Exp(1) (its perpendicular part is
independent of the tagged one's); the u-moments are Gamma functions. Every H = beta P times a polynomial in a,
1/a (down to a^-p) and beta with rational coefficients (the 1/(1 - a) cancel).
Checks: H(1; 0, 0) gives v1 (A2)'s xi_ki (tests/theory/test_sonine_moments.cpp), one species at p = 2 gives
van Noije-Ernst's a_2, and the a_2-only system equals MG's (theory/sonine_system.hpp) to rounding.

Writes the C++ table to stdout (about 30 s, needs only sympy):
    python3 scripts/derive_sonine_moments.py > theory/sonine_moment_table.cpp
"""
import sys
import sympy as sp

from generated_table import print_table

P_MAX = 3
a, b, u, W, s, si = sp.symbols("a beta u W s s_i", positive=True)


def sonine(p, x):
    return sp.expand(sp.assoc_laguerre(p, sp.Rational(1, 2), x))


def expect(expr):
    """E over W ~ N(0, (1 - a)/2), s, s_i ~ Exp(1) of a polynomial in W, s, s_i."""
    out = 0
    for (i, j, l), cf in sp.Poly(sp.expand(expr), W, s, si).terms():
        mW = 0 if i % 2 else (sp.factorial2(i - 1) * ((1 - a) / 2) ** (i // 2) if i else 1)
        out += cf * mW * sp.factorial(j) * sp.factorial(l)
    return sp.expand(sp.cancel(sp.together(out)))


def moment(p, q, r):
    ck2 = s + (W + a * u) ** 2
    ck2p = s + (W + a * u - b * u) ** 2
    ci2 = si + a * (W - (1 - a) * u) ** 2 / (1 - a)
    e = expect(sonine(q, ck2) * sonine(r, ci2) * (ck2p**p - ck2**p))
    tot = 0
    for (n,), cf in sp.Poly(e, u).terms():  # 4 pi int_0^inf u phi_V u^n du / P = 2 a Gamma((n+2)/2) a^(-(n+2)/2)
        tot += cf * 2 * a * a ** (-sp.Rational(n + 2, 2)) * sp.gamma(sp.Rational(n + 2, 2))
    return sp.expand(sp.simplify(sp.expand(tot / b)))


# Sources: 0 Maxwell, 1..P_MAX-1 the tagged species' a_2.., then the partner's a_2.. (the table's `source`).
SOURCES = [(0, 0)] + [(q, 0) for q in range(2, P_MAX + 1)] + [(0, r) for r in range(2, P_MAX + 1)]


def main():
    rows = []
    for p in range(1, P_MAX + 1):
        for src, (q, r) in enumerate(SOURCES):
            poly = sp.Poly(sp.expand(moment(p, q, r) * a**P_MAX), a, b)
            for (ia, ib), cf in sorted(poly.terms()):
                if not cf.is_Rational:
                    sys.exit(f"H({p}; {q}, {r}): coefficient {cf} is not rational")
                rows.append(f"    {{{p}, {src}, {ia - P_MAX}, {ib}, {sp.Rational(cf).p}.0 / {sp.Rational(cf).q}.0}},")
    print_table("derive_sonine_moments.py", "H(p; source) / (beta P) = sum of coefficient * a^ia * beta^ib over the rows of (p, source)",
                "sonine_moment_table.hpp", "SonineMomentTerm", "sonine_moment_term_count", "sonine_moment_terms", rows)

if __name__ == "__main__":
    main()
