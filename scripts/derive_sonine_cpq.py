#!/usr/bin/env python3
"""Closed forms of the tracer-diffusion collision integrals C_pq, p, q < 5 (theory/sonine/sonine_cpq_table.cpp).

C_pq = <S_q(c^2) int dsigma Theta(g.sigma)(g.sigma) c.[c S_p(c^2) - c' S_p(c'^2)]> over the Maxwellians of the
tagged species k and its partner i (docs/physics-beyond.md section 3), S_p = L_p^(3/2) (Sonine), c = v/sqrt(2 theta_k),
theta = T/m, c' after the collision v' = v - beta (g.sigma) sigma, beta = mu_ik (1 + eps); and (sources 2, 3) the
same with the partner's scalar Sonine weight S_r^(1/2)(c_i^2) inside the average, so that a partner with
f_i = f_M,i[1 + a_i2 S_2 + a_i3 S_3] gives C_pq + a_i2 C_pq^(2) + a_i3 C_pq^(3). The pair average is exact
(scripts/sonine_pair_algebra.py: given the normal relative speed the pair splits into Gaussian and exponential
parts). Every C_pq is beta P times a polynomial in a = theta_k/V, 1/a (down to a^-p) and beta with rational
coefficients, P = n_i sigma_ki^2 chi_ki sqrt(2 pi V), V = theta_k + theta_i. p, q < 2 are the closed forms of
theory/sonine/sonine2_diffusion.cpp.

Writes the C++ table to stdout (about 1 min, needs only sympy):
    python3 scripts/derive_sonine_cpq.py > theory/sonine/sonine_cpq_table.cpp
tests/theory/test_sonine_modes.cpp checks the table, all three sources, against an independent quadrature.
"""
import sympy as sp

from generated_table import print_table, term_rows
from sonine_pair_algebra import laguerre_of, pair, pair_average, poly

MODES = 5
SOURCES = [0, 2, 3]  # Maxwellian partner; its a_2; its a_3


def cpq(p, q, source=0):
    """C_pq/(beta P) as {(power of a, power of beta): Rational}."""
    c2, c2p, cc, ci2 = pair()
    weight = laguerre_of(source, sp.Rational(1, 2), ci2) if source else poly(1)
    e = weight * laguerre_of(q, sp.Rational(3, 2), c2) * (c2 * laguerre_of(p, sp.Rational(3, 2), c2) - cc * laguerre_of(p, sp.Rational(3, 2), c2p))
    return pair_average(e, f"C_{p}{q} (source {source})")


def main():
    rows = []
    for src, rs in enumerate(SOURCES):
        for p in range(MODES):
            for q in range(MODES):
                rows += term_rows((src, p, q), cpq(p, q, rs), f"C_{p}{q} (source {rs})")  # a^-p is the lowest power
    print_table("derive_sonine_cpq.py", "C_pq / (beta P) = sum of coefficient * a^ia * beta^ib over the rows of (source, p, q)",
                "sonine_cpq_table.hpp", "SonineCpqTerm", "sonine_cpq_term_count", "sonine_cpq_terms", rows)

if __name__ == "__main__":
    main()
