#!/usr/bin/env python3
"""Model-error bounds of the MG distribution scenes (mg-fig02, mg-fig03, mg-fig07-*), computed, not fitted.

The judged theory is the first-Sonine HCS of the mixture (c_k = 2 a2,k, Phi_k = Phi_M (1 + a2,k S2)). Its
next order is not available for mixtures; the computed proxy is the one-species second Sonine approximation
at the same restitution (granmix hcs ... --json -> "one_species_truncation", theory/sonine/sonine_truncation.hpp),
applied to each species' own a2,k as relative changes:
  c:     |a2[2] - a2[1]| / |a2[1]|                                   (linear second-Sonine scheme)
  Phi/G: |Phi[2] - Phi[1]| / Phi[1], Phi[2] = 1 + a2,k (a2[2]/a2[1]) S2(x) + a2,k (a3[2]/a2[1]) S3(x)
  Delta: |(a3/a2) S3(x)|, a3 with a2 held at a2[1] (Santos-Montanero; the scheme our DSMC supports),
         an absolute shift because DSMC builds Delta from its own measured c
with x = lambda_k v*^2 (MG Eq. 27). Each bound is the maximum over the scene's judged range of v* (a
per-point value vanishes where the correction crosses zero, while the true error need not).
Usage: scripts/mg_truncation_bounds.py [path/to/granmix]
"""
import json, subprocess, sys

granmix = sys.argv[1] if len(sys.argv) > 1 else "build/granmix"
# The Sonine polynomials of theory/sonine/sonine_polynomials.hpp (d = 3, x = c^2; S_n(0) > 0), restated here because
# the bounds below scale the one-species changes to each MIXTURE species' own a2,k, which
# SonineTruncation::phi_relative / delta_shift (one species, its own a2[1]) do not; a2, a3 themselves come from
# granmix hcs (theory/sonine/sonine_second_order.cpp), not from this script.
S2 = lambda x: 0.5 * x * x - 2.5 * x + 15 / 8
S3 = lambda x: -x**3 / 6 + 1.75 * x * x - 35 / 8 * x + 35 / 16


def hcs(mu, delta, w, alpha):
    out = subprocess.run([granmix, "hcs", "--mu", str(mu), "--delta", str(delta), "--w", str(w), "--alpha", str(alpha), "--json"],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def species(h, mu, delta):
    """a2,k and lambda_k (MG: v0^2 = 2T(m1+m2)/(m1 m2), T = sum x_k T_k, lambda_k = m_k v0^2 / (2 T_k))."""
    m = [mu, 1.0]
    x1 = delta / (1 + delta)
    ratio = [s["T_ratio_sonine"] for s in h["species"]]  # T_k / T_1
    T = x1 * ratio[0] + (1 - x1) * ratio[1]
    return [(h["species"][k]["c"] / 2, m[k] * (m[0] + m[1]) / (m[0] * m[1]) * T / ratio[k]) for k in range(2)]


def grid(vmax, n=481):
    return [vmax * i / (n - 1) for i in range(n)]


def phi_bound(h, a2k, lam, vmax):
    t = h["one_species_truncation"]
    f2, f3 = t["a2_sonine2"] / t["a2_sonine1"], t["a3_sonine2"] / t["a2_sonine1"]
    best = (0.0, 0.0)
    for v in grid(vmax):
        x = lam * v * v
        p1 = 1 + a2k * S2(x)
        r = abs(a2k * (f2 - 1) * S2(x) + a2k * f3 * S3(x)) / abs(p1)
        best = max(best, (r, v))
    return best


def delta_bound(h, lam, vmax):
    t = h["one_species_truncation"]
    r = t["a3_given_a2_sonine1"] / t["a2_sonine1"]
    return max((abs(r * S3(lam * v * v)), v) for v in grid(vmax)), r


if __name__ == "__main__":
    print("mg-fig02 c (mu 2, delta 1, w 1): |a2[2]-a2[1]|/|a2[1]| at the DSMC alphas")
    for a in (0.3, 0.5, 0.9):
        print(f"  alpha {a}: {hcs(2, 1, 1, a)['one_species_truncation']['a2_relative_change']:.4f}")
    for scene, a, ks, vmax in (("mg-fig03 phi", 0.5, (0, 1), 1.2), ("mg-fig07-alpha0.3 G", 0.3, (0,), 1.2), ("mg-fig07-alpha0.5 G", 0.5, (0,), 1.2)):
        h = hcs(4, 0.5, 1, a)
        sp = species(h, 4, 0.5)
        for k in ks:
            r, v = phi_bound(h, sp[k][0], sp[k][1], vmax)
            print(f"{scene} species {k + 1} (a2 {sp[k][0]:.4f}, lambda {sp[k][1]:.3f}): max relative change of Phi over v* <= {vmax}: {r:.4f} (at v* = {v:.3f})")
    h = hcs(4, 0.5, 1, 0.5)
    (s, v), r = delta_bound(h, species(h, 4, 0.5)[0][1], 1.1)
    print(f"mg-fig03 Delta1: a3/a2 = {r:.4f}; max |(a3/a2) S3(lambda1 v*^2)| over v* <= 1.1: {s:.4f} (at v* = {v:.3f})")
