#!/usr/bin/env python3
"""What limits MG's gamma = T1/T2: the Sonine sequence of the HCS beyond the orders granmix ships.

An independent implementation of the binary HCS at Sonine order K (f_k = f_M,k [1 + sum_{q=2..K} a_kq S_q(c^2)],
S_q = L_q^(1/2)), from the exact pair moments H(p; q, r) of scripts/derive_sonine_moments.py (sympy), solved by
Newton in ln(theta2/theta1) and the a's, in two closures:
  linear  (granmix's): the rates linear in the a's, the product of zeta's a-part with the moments' a-part dropped
          (theory/sonine/sonine_moment_cooling.hpp), K = 2 (MG's first Sonine), 3 (granmix's order 3) and 4 (not shipped);
  full    K = 3 with every product kept (the moment equations exact for the truncated ansatz: a_k a_i collision
          terms and zeta(a) <c^2p>(a)).
Orders 2 and 3 (linear) are checked against `granmix hcs --json` (T_ratio_sonine, T_ratio_sonine3) to 1e-6.
The DSMC column is the mean of the paper-fidelity runs, seeds 1-3, of mg-fig04-* and mg-fig05-* (docs/validation.md,
sigma ~ 0.1%). Prints one TSV row per point: the relative gaps theory/DSMC - 1 and the first species' c = 2 a_12.
Usage: scripts/mg_gamma_sonine_orders.py [path/to/granmix]   (about 30 s; needs only sympy)
"""
import json, math, subprocess, sys

import sympy as sp

from derive_sonine_moments import moment

granmix = sys.argv[1] if len(sys.argv) > 1 else "build/granmix"
K_MAX = 4
H = {}
for p in range(1, K_MAX + 1):
    for q in [0] + list(range(2, K_MAX + 1)):
        for r in [0] + list(range(2, K_MAX + 1)):
            if q and r and max(p, q, r) > 3:
                continue  # products are needed at K = 3 only (the full closure)
            H[p, q, r] = [(ia, ib, float(cf)) for (ia, ib), cf in moment(p, q, r).items()]


def h(p, q, r, a, b):
    return sum(c * a**ia * b**ib for ia, ib, c in H[p, q, r])


def m(p):  # <c^2p> over the Maxwellian, c^2 ~ Gamma(3/2)
    return math.gamma(p + 1.5) / math.gamma(1.5)


def w(p, q):  # <c^2p S_q(c^2)> / <c^2p>: <c^4> = m(2)(1 + a2), <c^6> = m(3)(1 + 3a2 - a3), ... (S_q = L_q^(1/2))
    return float(sum((-1) ** j * sp.binomial(q + sp.Rational(1, 2), q - j) / sp.factorial(j) * sp.rf(p + sp.Rational(3, 2), j)
                     for j in range(q + 1)))


def hcs_gamma(mu, delta, alpha, K, full=False):
    """gamma = T1/T2 and c_1 of the MG binary (montanero_garzo_binary: m = mu, 1; sigma = 1, 1; x1 = delta/(1+delta)).
    Equations: equal cooling rates zeta_1 = zeta_2 (MG Eq. 45) and the steady balances of <c^2p>_k, p = 2..K,
    d<c^2p>/dt = R_kp + p zeta_k <c^2p> = 0 (theory/sonine/sonine_moment_cooling.hpp), zeta_k = -R_k1 / (3/2)."""
    x1 = delta / (1 + delta)
    mix = [(mu, x1), (1.0, 1 - x1)]
    Q = list(range(2, K + 1))

    def equations(x):
        th = [1.0, math.exp(x[0])]
        A = [dict([(0, 1.0)] + [(q, x[1 + s * len(Q) + j]) for j, q in enumerate(Q)]) for s in range(2)]
        R = [[0.0] * (K + 1) for _ in range(2)]
        R0 = [[0.0] * (K + 1) for _ in range(2)]
        for k in range(2):
            for i in range(2):
                V = th[k] + th[i]
                a, beta = th[k] / V, mix[i][0] / (mix[i][0] + mix[k][0]) * (1 + alpha)
                P = beta * mix[i][1] * math.sqrt(2 * math.pi * V)
                for p in range(1, K + 1):
                    R0[k][p] += P * h(p, 0, 0, a, beta)
                    R[k][p] += P * sum(A[k][q] * A[i][r] * h(p, q, r, a, beta) for q in A[k] for r in A[i] if full or not (q and r))
        zeta = [-R[k][1] / m(1) for k in range(2)]
        zeta0 = [-R0[k][1] / m(1) for k in range(2)]
        eq = [zeta[0] - zeta[1]]
        for k in range(2):
            for p in Q:
                shape = 1 + sum(A[k][q] * w(p, q) for q in Q)
                change = zeta[k] * m(p) * shape if full else zeta0[k] * m(p) * shape + (zeta[k] - zeta0[k]) * m(p)
                eq.append(R[k][p] + p * change)
        return eq

    x = [0.0] * (1 + 2 * len(Q))
    for _ in range(100):
        f = equations(x)
        J = [[0.0] * len(x) for _ in x]
        for j in range(len(x)):
            y = x[:]
            y[j] += 1e-7
            fj = equations(y)
            for i in range(len(x)):
                J[i][j] = (fj[i] - f[i]) / 1e-7
        dx = [float(v) for v in sp.Matrix(J).LUsolve(sp.Matrix([-v for v in f]))]
        x = [a + d for a, d in zip(x, dx)]
        if max(abs(d) for d in dx) < 1e-13:
            break
    else:
        sys.exit(f"mu {mu} delta {delta} alpha {alpha} K {K}: Newton did not converge")
    return mu / math.exp(x[0]), 2 * x[1]


# Mean of the paper-fidelity DSMC, seeds 1-3 (mg-fig04-mu*, mg-fig05-delta*; docs/validation.md).
DSMC = {(2, 2): (1.53621, 1.34396, 1.11925), (10, 2): (5.31174, 3.79934, 1.94476), (0.1, 2): (0.12653, 0.18872, 0.45708),
        (4, 0.25): (3.45248, 2.38897, 1.35309), (4, 1): (2.69027, 2.05299, 1.32944), (4, 4): (2.36696, 1.88790, 1.30998)}
print("\t".join(["mu", "delta", "alpha", "gamma_dsmc", "gap_order2", "gap_order3", "gap_order4", "gap_order3_full", "c1_order2",
                 "c1_order3", "c1_order4"]))
for (mu, delta), values in DSMC.items():
    for alpha, g in zip((0.3, 0.5, 0.8), values):
        orders = {K: hcs_gamma(mu, delta, alpha, K) for K in (2, 3, 4)}
        full = hcs_gamma(mu, delta, alpha, 3, full=True)
        ref = json.loads(subprocess.run([granmix, "hcs", "--mu", str(mu), "--delta", str(delta), "--w", "1", "--alpha", str(alpha), "--json"],
                                        check=True, capture_output=True, text=True).stdout)["species"][1]
        for K, key in ((2, "T_ratio_sonine"), (3, "T_ratio_sonine3")):  # granmix's species 2 row: T2/T1 = 1/gamma
            if abs(orders[K][0] * ref[key] - 1) > 1e-6:
                sys.exit(f"mu {mu} delta {delta} alpha {alpha}: order {K} gamma {orders[K][0]} but granmix hcs says {1 / ref[key]}")
        gaps = ["%+.4f" % (orders[K][0] / g - 1) for K in (2, 3, 4)] + ["%+.4f" % (full[0] / g - 1)]
        print("\t".join([str(mu), str(delta), str(alpha), str(g)] + gaps + ["%.4f" % orders[K][1] for K in (2, 3, 4)]))
