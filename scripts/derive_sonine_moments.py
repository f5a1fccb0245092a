#!/usr/bin/env python3
"""Closed forms of the scalar Sonine collision moments H(p; q, r), p = 1..4 (theory/sonine/sonine_moment_table.cpp).

The kinetic level's temperatures with a_2, a_3 (order 3) and a_4 (order 4) per species (theory/sonine/sonine_moment_cooling.hpp):
species k's distribution is f_k = f_M,k [1 + sum_q a_kq S_q(c^2)], S_p = L_p^(1/2) (the scalar Sonine polynomials),
c = v/sqrt(2 theta_k), theta = T/m. The collisional rate of <c^(2p)>_k at fixed theta_k from collisions with
species i, linear in the a's (products a a dropped, as Garzo-Dufty/MG do at first Sonine), is

    R_p = P [H(p; 0, 0) + sum_q a_kq H(p; q, 0) + sum_r a_ir H(p; 0, r)],
    H(p; q, r) = <S_q(c_k^2) S_r(c_i^2) int dsigma Theta(g.sigma)(g.sigma) [c_k'^(2p) - c_k^(2p)]>

over the Maxwellians of k and i, P = n_i sigma_ki^2 chi_ki sqrt(2 pi V), V = theta_k + theta_i, c' after the
collision v_k' = v_k - beta (g.sigma) sigma, beta = mu_ik (1 + eps); the pair average is exact
(scripts/sonine_pair_algebra.py). Every H = beta P times a polynomial in a = theta_k/V, 1/a and beta with rational
coefficients.
Checks (tests/theory/test_sonine_moments.cpp): the table against a quadrature over both Maxwellians (p = 1..4); the a_2-only
system equals MG's first Sonine (theory/sonine/sonine_system.hpp, whose p = 1 is v1 (A2)'s xi_ki) to rounding; one species
settles at Brilliantov & Poschel's second-Sonine a_2, a_3.

Writes the C++ table to stdout (about 2 s, needs only sympy):
    python3 scripts/derive_sonine_moments.py > theory/sonine/sonine_moment_table.cpp
"""
import sympy as sp

from generated_table import print_table, term_rows
from sonine_pair_algebra import laguerre_of, pair, pair_average

P_MAX = 4


def moment(p, q, r):
    """H(p; q, r)/(beta P) as {(power of a, power of beta): Rational}."""
    c2, c2p, _, ci2 = pair()
    e = laguerre_of(q, sp.Rational(1, 2), c2) * laguerre_of(r, sp.Rational(1, 2), ci2) * (c2p**p - c2**p)
    return pair_average(e, f"H({p}; {q}, {r})")


# Sources: 0 Maxwell, 1..P_MAX-1 the tagged species' a_2.., then the partner's a_2.. (the table's `source`).
SOURCES = [(0, 0)] + [(q, 0) for q in range(2, P_MAX + 1)] + [(0, r) for r in range(2, P_MAX + 1)]


def main():
    rows = []
    for p in range(1, P_MAX + 1):
        for src, (q, r) in enumerate(SOURCES):
            rows += term_rows((p, src), moment(p, q, r), f"H({p}; {q}, {r})")
    print_table("derive_sonine_moments.py", "H(p; source) / (beta P) = sum of coefficient * a^ia * beta^ib over the rows of (p, source)",
                "sonine_moment_table.hpp", "SonineMomentTerm", "sonine_moment_term_count", "sonine_moment_terms", rows)

if __name__ == "__main__":
    main()
