#pragma once
// Random streams of the DSMC: one pcg64 stream per replica, derived from (master seed, replica),
// so results are identical for any number of threads (docs/architecture.md §5). The distributions are
// written here, not taken from <random>, so that a stream gives the same numbers with every
// standard library.
#include <pcg_random.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <cstring>
#include <string>
#include <type_traits>
#include <utility>

namespace granmix::dsmc {

struct Vec3 {
  double x, y, z;
};

inline double norm2(const Vec3& v) { return v.x * v.x + v.y * v.y + v.z * v.z; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }

// Ziggurat tables of e^{-x} (Marsaglia & Tsang 2000): 256 layers of equal area V, x[1] = r the start of
// the tail, x[0] = V / f(r) the base layer's pseudo-width, x[256] = 0, f = e^{-x}.
struct ExpZiggurat {
  double x[257], f[257];
  ExpZiggurat() {
    const double r = 7.69711747013104972, V = 0.0039496598225815571993;
    x[0] = V / std::exp(-r), x[1] = r, x[256] = 0.0;
    for (int i = 2; i < 256; ++i) x[i] = -std::log(V / x[i - 1] + std::exp(-x[i - 1]));
    for (int i = 0; i < 257; ++i) f[i] = std::exp(-x[i]);
  }
};
inline const ExpZiggurat exp_ziggurat{};

class Rng {
 public:
  Rng(std::uint64_t seed, std::uint64_t replica) : gen_(seed, replica) {}

  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(gen_() >> 11) * 0x1.0p-53; }
  // Uniform in (0, 1]: safe under a logarithm.
  double uniform_open0() { return (static_cast<double>(gen_() >> 11) + 1.0) * 0x1.0p-53; }
  // Uniform integer in [0, n): Lemire's multiply-shift with rejection (unbiased).
  std::uint64_t below(std::uint64_t n) {
    for (;;) {
      const __uint128_t m = static_cast<__uint128_t>(gen_()) * n;
      const std::uint64_t low = static_cast<std::uint64_t>(m);
      if (low >= n || low >= (-n) % n) return static_cast<std::uint64_t>(m >> 64);
    }
  }
  // Two uniform integers in [0, n1) and [0, n2) (n < 2^32) from the two halves of one 64-bit word, by
  // Lemire's multiply-shift on 32 bits each (a half in the rejection zone is redrawn alone: the
  // halves are independent, so the pair stays unbiased). One draw and two 32-bit products instead
  // of two draws and two 128-bit products per proposed pair.
  std::pair<std::uint32_t, std::uint32_t> below_pair(std::uint32_t n1, std::uint32_t n2) {
    const std::uint64_t w = gen_();
    return {below32(static_cast<std::uint32_t>(w), n1), below32(static_cast<std::uint32_t>(w >> 32), n2)};
  }
  // Standard normal, Marsaglia's polar method (no cached second value: simpler to reproduce).
  double normal() {
    for (;;) {
      const double u = 2.0 * uniform() - 1.0, v = 2.0 * uniform() - 1.0, s = u * u + v * v;
      if (s > 0.0 && s < 1.0) return u * std::sqrt(-2.0 * std::log(s) / s);
    }
  }
  // Exponential waiting time of a Poisson process of the given rate.
  double exponential(double rate) { return -std::log(uniform_open0()) / rate; }
  // Exponential of mean 1 by Marsaglia & Tsang's ziggurat (J. Stat. Softw. 5(8), 2000), 256 layers:
  // 98.9% of draws cost one random word, two table loads and a multiply, without the log, which takes
  // 5% of the event loop in perf. Layer i: the low 8 bits; the point in it: the high 53 bits.
  double standard_exponential() {
    const ExpZiggurat& z = exp_ziggurat;
    for (;;) {
      const std::uint64_t bits = gen_();
      const std::size_t i = bits & 0xff;
      const double x = static_cast<double>(bits >> 11) * 0x1.0p-53 * z.x[i];
      if (x < z.x[i + 1]) return x;                                // inside the layer's rectangle
      if (i == 0) return z.x[1] - std::log(uniform_open0());        // the tail beyond r: r + Exp(1)
      if (z.f[i + 1] + (z.f[i] - z.f[i + 1]) * uniform() < std::exp(-x)) return x;  // the wedge
    }
  }

  // Unit vector uniform on the sphere (Archimedes: z uniform in [-1, 1]).
  Vec3 unit_vector() {
    const double z = 2.0 * uniform() - 1.0, r = std::sqrt(1.0 - z * z), phi = 2.0 * std::numbers::pi * uniform();
    return {r * std::cos(phi), r * std::sin(phi), z};
  }

  // Unit vector e around the unit vector n with density ∝ (n·e) on the hemisphere n·e > 0:
  // cos θ = √u, the distribution of collision directions weighted by the normal speed. One point
  // (x, y) uniform in the unit disk gives both: r² is uniform (so cos θ = r) and (x, y)/r is the
  // azimuth, without sin/cos (which cost 5% of the loop in perf).
  Vec3 hemisphere(const Vec3& n) {
    double x, y, r2;
    do {
      x = 2.0 * uniform() - 1.0, y = 2.0 * uniform() - 1.0, r2 = x * x + y * y;
    } while (!(r2 < 1.0 && r2 > 0.0));
    const double c = std::sqrt(r2), s = std::sqrt(1.0 - r2), f = s / c;
    // Orthonormal p, q perpendicular to n (branch-free construction of Duff et al. 2017).
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z), b = n.x * n.y * a;
    const Vec3 p{1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
    const Vec3 q{b, sign + n.y * n.y * a, -n.y};
    const double cp = f * x, cq = f * y;
    return {c * n.x + cp * p.x + cq * q.x, c * n.y + cp * p.y + cq * q.y, c * n.z + cp * p.z + cq * q.z};
  }

  // The generator's state (its bytes: pcg's text form does not compile with 128-bit words in
  // GCC 12), for snapshots of a replica in flight; restore() refuses bytes of another size. (The
  // snapshot's identity and checksum make sure they are this replica's.)
  std::string state() const {
    static_assert(std::is_trivially_copyable_v<pcg64>);
    return std::string(reinterpret_cast<const char*>(&gen_), sizeof gen_);
  }
  bool restore(const std::string& bytes) {
    if (bytes.size() != sizeof gen_) return false;
    pcg64 g;
    std::memcpy(static_cast<void*>(&g), bytes.data(), sizeof g);
    gen_ = g;
    return true;
  }

 private:
  std::uint32_t below32(std::uint32_t x, std::uint32_t n) {
    for (;;) {
      const std::uint64_t m = static_cast<std::uint64_t>(x) * n;
      const auto low = static_cast<std::uint32_t>(m);
      if (low >= n || low >= static_cast<std::uint32_t>(-n) % n) return static_cast<std::uint32_t>(m >> 32);
      x = static_cast<std::uint32_t>(gen_());
    }
  }
  pcg64 gen_;
};

}  // namespace granmix::dsmc
