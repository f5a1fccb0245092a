// Study (docs/levels.md, "v2 Fig. 5's intruder"): the stationary temperature of a tracer intruder in a homogeneously cooling
// gas, by a Monte Carlo of the tagged-particle (Boltzmann–Lorentz) problem, written independently of theory/.
// Build and run (no dependencies; ~10 s per 1e6 time units):
//   g++ -O2 -std=c++20 scripts/tracer_intruder_mc.cpp -o /tmp/tracer_intruder_mc
//   /tmp/tracer_intruder_mc zeta=0.17898878 a2=0.052459 self_consistent=1
// Units: gas m₁ = 1, T₁ = 1 at the reference time, velocities scaled with the gas's thermal speed, s the matching clock
// (ds = dt v_th(t)/v_th(0)); the process is then stationary (tests/theory/tagged_particle_mc.hpp, the same problem):
// between collisions du/ds = (ζ/2)u, collisions with gas particles of velocity w at the rate n₁σ₁₂²χ π|u − w| over the
// gas's distribution f_M(w)(1 + a₂S₂(w²/2)) (its first Sonine shape, S₂(x) = x²/2 − 5x/2 + 15/8), σ̂ ∝ (ĝ·σ̂),
// u′ = u − μ(1+ε)(g·σ̂)σ̂, μ = m₁/(m₁ + m₂). Printed: θ = T₂/T₁ = m₂⟨u²⟩/3 (50 batch means after the burn-in), and
// the intruder's a₂ = (3/5)⟨u⁴⟩/⟨u²⟩² − 1, ξ₁₂ = −n₂⟨ΔE_gas⟩/(n₁ 3/2), the gas's heating by the intruders (the gas's energy gains in the same collisions).
// Check: an elastic intruder in a gas at rest in time (eps=1 zeta=0 a2=0 theta0=1) gives θ = 1.00, a₂ = 0.001/−0.0002
// (two seeds, 1e6 time units).
// self_consistent=1: ζ = zeta + ξ₁₂(θ) (the gas cools at its own rate plus the intruders' heating), four passes (the fixed point contracts by ~0.16 per pass here).
// Defaults: v2 Fig. 5 (v1 Fig. 3's gas, m₂ = 100, σ₂ = 100^(1/3), n₂ = 1e-5, ε = 0.5) with the gas's one-species
// first-Sonine a₂ = c₁/2 = 0.052459 and rate ζ = ξ₁₁(1 + 3c₁/32) = 0.17898878 (granmix hcs on the gas alone).
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace {

using Vec = std::array<double, 3>;
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

struct Params {
  double m2 = 100, eps = 0.5, n1 = 0.1, n2 = 1e-5, sigma12 = 0.5 * (1 + std::cbrt(100.0)), a2 = 0.052459, zeta = 0.17898878;
  double theta0 = 504.6, length = 1e6, burn = 2000;
  unsigned long seed = 1;
};

struct Result {
  double theta, err, xi12, a2;  // a2: the intruder's own, (3/5)⟨u⁴⟩/⟨u²⟩² − 1
  long collisions;
};

Result run(const Params& p, double zeta) {
  std::mt19937_64 rng(p.seed);
  std::normal_distribution<double> N01;
  std::uniform_real_distribution<double> U01;
  std::gamma_distribution<double> g32(1.5), g52(2.5), g72(3.5);
  // x = |w|²/2 has density Σ_j c_j Gamma(j; x): c_3/2 = 1 + 15a₂/8, c_5/2 = −15a₂/4, c_7/2 = 15a₂/8. Proposal: the
  // positive terms; accept with f/q ≤ 1. |w| ≤ W = 8 (the rest, x > 32, weighs e^−32).
  const double W = 8.0, c[3] = {1 + 1.875 * p.a2, -3.75 * p.a2, 1.875 * p.a2}, norm[3] = {0.886226925452758, 1.329340388179137, 3.323350970447843};
  auto gamma_pdf = [&](int j, double x) { return std::pow(x, 0.5 + j) * std::exp(-x) / norm[j]; };
  auto gas = [&]() {
    double positive = 0;
    for (double cj : c) positive += std::max(cj, 0.0);
    for (;;) {
      double pick = U01(rng) * positive, x = 0;
      for (int j = 0; j < 3; ++j) {
        if (c[j] <= 0) continue;
        if (pick < c[j]) {
          x = j == 0 ? g32(rng) : j == 1 ? g52(rng) : g72(rng);
          break;
        }
        pick -= c[j];
      }
      double f = 0, q = 0;
      for (int j = 0; j < 3; ++j) f += c[j] * gamma_pdf(j, x), q += std::max(c[j], 0.0) * gamma_pdf(j, x);
      const double r = std::sqrt(2 * x);
      if (U01(rng) * q >= f || r > W) continue;
      Vec d{N01(rng), N01(rng), N01(rng)};
      const double nd = std::sqrt(dot(d, d));
      return Vec{r * d[0] / nd, r * d[1] / nd, r * d[2] / nd};
    }
  };
  const double flux = p.n1 * p.sigma12 * p.sigma12 * std::numbers::pi, mu = 1 / (1 + p.m2), beta = mu * (1 + p.eps);
  const double sd0 = std::sqrt(p.theta0 / p.m2);
  Vec u{sd0 * N01(rng), sd0 * N01(rng), sd0 * N01(rng)};
  constexpr int batches = 50;
  std::vector<double> u2_time(batches, 0), time(batches, 0);
  double u4_time = 0;
  double s = 0, gas_gain = 0;
  long collisions = 0;
  while (s < p.length) {
    // Thinning over one mean free time h at the present speed: |u| ≤ umax there, |w| ≤ W.
    const double speed = std::sqrt(dot(u, u)), h = 1 / (flux * (speed + W)), umax = speed * std::exp(0.5 * zeta * h);
    const double rate = flux * (umax + W);
    double wait = -std::log1p(-U01(rng)) / rate;
    const bool candidate = wait <= h;
    if (!candidate) wait = h;
    if (s > p.burn) {  // ∫u² ds exactly over the free flight
      const int b = std::min(batches - 1, int((s - p.burn) / (p.length - p.burn) * batches));
      u2_time[b] += zeta > 0 ? speed * speed * std::expm1(zeta * wait) / zeta : speed * speed * wait;
      time[b] += wait;
      u4_time += zeta > 0 ? std::pow(speed, 4) * std::expm1(2 * zeta * wait) / (2 * zeta) : std::pow(speed, 4) * wait;
    }
    for (double& x : u) x *= std::exp(0.5 * zeta * wait);
    s += wait;
    if (!candidate) continue;
    const Vec w = gas(), g{u[0] - w[0], u[1] - w[1], u[2] - w[2]};
    const double gn = std::sqrt(dot(g, g));
    if (U01(rng) * (umax + W) >= gn) continue;
    const Vec e3{g[0] / gn, g[1] / gn, g[2] / gn}, t = std::abs(e3[0]) < 0.9 ? Vec{1, 0, 0} : Vec{0, 1, 0};
    Vec e1{t[0] - dot(t, e3) * e3[0], t[1] - dot(t, e3) * e3[1], t[2] - dot(t, e3) * e3[2]};
    const double n1 = std::sqrt(dot(e1, e1));
    for (double& x : e1) x /= n1;
    const Vec e2{e3[1] * e1[2] - e3[2] * e1[1], e3[2] * e1[0] - e3[0] * e1[2], e3[0] * e1[1] - e3[1] * e1[0]};
    const double ct = std::sqrt(U01(rng)), st = std::sqrt(1 - ct * ct), phi = 2 * std::numbers::pi * U01(rng);
    Vec sigma;
    for (int d = 0; d < 3; ++d) sigma[d] = st * std::cos(phi) * e1[d] + st * std::sin(phi) * e2[d] + ct * e3[d];
    Vec w_after = w;
    for (int d = 0; d < 3; ++d) w_after[d] += (1 - mu) * (1 + p.eps) * gn * ct * sigma[d], u[d] -= beta * gn * ct * sigma[d];
    if (s > p.burn) gas_gain += 0.5 * (dot(w_after, w_after) - dot(w, w));
    ++collisions;
  }
  double m = 0, m2 = 0, u2 = 0, t = 0;
  for (int b = 0; b < batches; ++b) u2 += u2_time[b], t += time[b];
  const double a2 = 0.6 * (u4_time / t) / ((u2 / t) * (u2 / t)) - 1;
  for (int b = 0; b < batches; ++b) {
    const double th = u2_time[b] / time[b] * p.m2 / 3;
    m += th / batches, m2 += th * th / batches;
  }
  return {m, std::sqrt((m2 - m * m) / (batches - 1)), -(p.n2 * gas_gain / (p.length - p.burn)) / (1.5 * p.n1), a2, collisions};
}

}  // namespace

int main(int argc, char** argv) {
  Params p;
  bool self_consistent = false;
  std::map<std::string, double*> keys = {{"m2", &p.m2},         {"eps", &p.eps},       {"n1", &p.n1},         {"n2", &p.n2},
                                         {"sigma12", &p.sigma12}, {"a2", &p.a2},         {"zeta", &p.zeta},     {"theta0", &p.theta0},
                                         {"length", &p.length},   {"burn", &p.burn}};
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    const auto eq = arg.find('=');
    const std::string key = arg.substr(0, eq);
    char* end = nullptr;
    const double v = eq == std::string::npos ? NAN : std::strtod(arg.c_str() + eq + 1, &end);
    if (!std::isfinite(v) || *end) {
      std::fprintf(stderr, "tracer_intruder_mc: argument %d '%s': expected key=number\n", a, arg.c_str());
      return 2;
    }
    if (key == "seed") p.seed = (unsigned long)v;
    else if (key == "self_consistent") self_consistent = v != 0;
    else if (keys.count(key)) *keys[key] = v;
    else {
      std::fprintf(stderr, "tracer_intruder_mc: unknown key '%s' (m2 eps n1 n2 sigma12 a2 zeta theta0 length burn seed self_consistent)\n", key.c_str());
      return 2;
    }
  }
  if (!(p.length > p.burn && p.burn >= 0 && p.m2 > 0 && p.eps >= 0 && p.eps <= 1 && p.zeta >= 0)) {
    std::fprintf(stderr, "tracer_intruder_mc: need length > burn >= 0, m2 > 0, 0 <= eps <= 1, zeta >= 0\n");
    return 2;
  }
  double zeta = p.zeta;
  for (int pass = 0; pass < (self_consistent ? 4 : 1); ++pass) {
    const Result r = run(p, zeta);
    std::printf("zeta %.6f: theta %.2f +- %.2f, intruder a2 %.4f, xi12 %.6f (xi12/zeta %.4f), %ld collisions\n", zeta, r.theta, r.err, r.a2,
                r.xi12, zeta > 0 ? r.xi12 / zeta : 0.0, r.collisions);
    zeta = p.zeta + r.xi12;
    p.seed += 1000, p.theta0 = r.theta;
  }
}
