// bo1-fig08 (θ = 3: n_k = 0.1 k^-3, σ_k = k^(1/3), ε = 0.5, equal start, 43 species): why the heavy
// rare species' MSD ratios ⟨R_k²⟩/⟨R_1²⟩ lie 30–80% above v1 Eq. (17). Measured per species and
// decade: T_k against the Maxwellian theory, the MSD against Eq. 17, the MSD that the Maxwellian
// velocity memory gives with the *measured* ⟨v²⟩ ("msd_T": isolates the temperatures), what is left
// (DSMC / msd_T: the velocity memory itself), ν_eff against ν_k over the decade, the pooled c_k and
// the spread of one replica's estimate against the Gaussian-displacement value √(2/(3 N_k)).
// Run at several N at fixed densities: a finite-size effect (total momentum, single-particle species
// and the drift that cancels their momentum, dsmc/particles.cpp) changes with N; a theory gap does not.
#include <fmt/format.h>

#include "gaps_parts.hpp"
#include "model/enskog.hpp"
#include "model/mixture_generators.hpp"
#include "theory/histories/msd.hpp"
#include "theory/histories/temperature_history.hpp"
#include "velocity_memory.hpp"

namespace granmix::bench {

namespace {

constexpr std::size_t heavy_from = 12;  // species 13–43: the scene's heavy group (1–38 particles at N = 1e5)
constexpr std::size_t heaviest_from = 26;  // species 27–43 (β_k nearest 1): where the memory gap lives

// Pooled series of one species: slot 0 all replicas, slot r + 1 replica r left out.
struct Pooled {
  std::vector<std::vector<double>> v2, v4, Q, M, M_T;
  std::vector<double> M_T_slow;  // all replicas, ν lowered by 1%: the MSD's sensitivity to the rate
};

std::size_t slot(std::size_t excluded) { return excluded == TaggedRun::npos ? 0 : excluded + 1; }

}  // namespace

GapsPart heavy_gaps(const StudyOptions& o, model::Table& replicas) {
  model::PowerLaw pl;
  pl.n1 = 0.1, pl.theta = 3, pl.n1_particles = 83000;  // compare/scenes/bo1-fig08.toml
  const model::Mixture mix = model::power_law_mixture(pl);
  const std::size_t S = mix.size();
  const model::Restitution law = model::Restitution::constant(S, 0.5);
  const std::vector<double> T0(S, 1.0);
  const std::size_t R = o.quick ? 2 : 8;
  const double t_end = o.quick ? 1e5 : 1e9;
  const std::vector<std::size_t> sizes = o.quick ? std::vector<std::size_t>{10000} : std::vector<std::size_t>{50000, 100000, 200000};
  const std::vector<double> t = log_grid(1e-4, t_end, 8);
  const std::size_t J = t.size();
  const theory::CollisionRates rates(mix, law, model::dilute_contact_values(S));
  theory::TemperatureOptions opt;
  opt.reduced_time = true, opt.vacf = true, opt.t_first = t.front();
  const theory::TemperatureHistory h(rates, T0, t_end, opt);
  std::vector<double> reports;
  for (double x = 1e3; x <= t_end * 1.0001; x *= 10) reports.push_back(x);
  std::vector<std::vector<double>> eq17(reports.size(), std::vector<double>(S));
  for (std::size_t i = 0; i < reports.size(); ++i)
    for (std::size_t k = 0; k < S; ++k) eq17[i][k] = theory::msd_eq17(h, k, reports[i]);

  GapsPart out;
  out.table.columns = {"particles_total", "species", "particles", "t", "T_ratio", "T_ratio_err", "T_ratio_theory", "T_over_theory",
                       "T_over_theory_err", "msd_ratio", "msd_ratio_err", "msd_ratio_eq17", "msd_ratio_vacf", "msd_over_eq17",
                       "msd_over_eq17_err", "msd_T_over_eq17", "msd_T_over_eq17_err", "memory", "memory_err", "nu_eff_over_nu",
                       "nu_eff_over_nu_err", "c", "c_err", "spread", "spread_gaussian", "z", "vacf_over_eq17", "msd_sensitivity"};
  replicas.columns = {"particles_total", "replica", "species", "particles", "t", "msd_ratio", "T_ratio", "msd_ratio_eq17"};
  for (std::size_t N : sizes) {
    const std::vector<std::size_t> counts = counts_at_least_one(mix, N);
    const TaggedRun run = run_tagged(mix, law, counts, T0, t, o.seed, R);
    std::size_t singles = 0;
    for (std::size_t c : counts) singles += c == 1;
    if (o.progress)
      o.progress(fmt::format("bo1-fig08: {} particles ({} species of one particle, heavy group {}-{} particles) x {} replicas to t = {:g}: "
                             "{:.1f} s, {:.3g} collisions",
                             N, singles, counts.back(), counts[heavy_from], R, t_end, run.seconds, double(run.collisions)));
    // First-Sonine rates at the measured temperatures (all replicas) per sample.
    std::vector<Rates> at_measured;
    for (std::size_t j = 0; j < J; ++j) {
      std::vector<double> T(S);
      for (std::size_t k = 0; k < S; ++k) T[k] = mix[k].mass * run.mean(j, k, TaggedRun::v2) / 3.0;
      at_measured.push_back(rates_at(rates, T));
    }
    std::vector<Pooled> pooled(S);
    for (std::size_t k = 0; k < S; ++k) {
      std::vector<double> nu(J);
      for (std::size_t j = 0; j < J; ++j) nu[j] = at_measured[j].nu[k];
      for (std::size_t s = 0; s <= R; ++s) {
        const std::size_t e = s == 0 ? TaggedRun::npos : s - 1;
        Pooled& p = pooled[k];
        p.v2.push_back(series(run, k, TaggedRun::v2, e)), p.v4.push_back(series(run, k, TaggedRun::v4, e));
        p.Q.push_back(series(run, k, TaggedRun::rv, e)), p.M.push_back(series(run, k, TaggedRun::r2, e));
        p.M_T.push_back(msd_from_memory(t, p.v2.back(), nu));
      }
      for (double& x : nu) x *= 0.99;
      pooled[k].M_T_slow = msd_from_memory(t, pooled[k].v2[0], nu);
    }
    for (std::size_t i = 0; i < reports.size(); ++i) {
      const std::size_t j = index_of(t, reports[i]), a = index_of(t, reports[i] / 10);
      const double T1_th = h.temperature(t[j], 0), M1_th = eq17[i][0], M1_vacf = h.msd_vacf(t[j], 0);
      // Per-species quantities as functions of the replica left out (jackknife).
      auto T_over = [&](std::size_t k, std::size_t e) { return pooled[k].v2[slot(e)][j] * mix[k].mass / 3.0 / h.temperature(t[j], k); };
      auto msd_over = [&](std::size_t k, std::size_t e) { return pooled[k].M[slot(e)][j] / eq17[i][k]; };
      auto msdT_over = [&](std::size_t k, std::size_t e) { return pooled[k].M_T[slot(e)][j] / eq17[i][k]; };
      auto memory = [&](std::size_t k, std::size_t e) { return pooled[k].M[slot(e)][j] / pooled[k].M_T[slot(e)][j]; };
      auto offset = [&](std::size_t k, std::size_t) { return h.msd_vacf(t[j], k) / eq17[i][k]; };
      auto cumulant = [&](std::size_t k, std::size_t e) { return cumulant_of(pooled[k].v2[slot(e)][j], pooled[k].v4[slot(e)][j]); };
      // d ln M / d ln ν of the Maxwellian-memory MSD: near β_k = 1 a small rate error is amplified.
      auto sensitivity = [&](std::size_t k, std::size_t) { return std::log(pooled[k].M_T_slow[j] / pooled[k].M_T[0][j]) / std::log(0.99); };
      auto nu_over = [&](std::size_t k, std::size_t e) {  // measured collisional loss of Q over the first-Sonine prediction
        const Pooled& p = pooled[k];
        std::vector<double> nuQ(J);
        for (std::size_t q = 0; q < J; ++q) nuQ[q] = at_measured[q].nu[k] * p.Q[slot(e)][q];
        const double predicted = integral_log_grid(t, nuQ, a, j) / integral_log_grid(t, p.Q[slot(e)], a, j);
        return effective_rate(t, p.v2[slot(e)], p.Q[slot(e)], a, j) / predicted;
      };
      for (std::size_t k = 0; k < S; ++k) {
        auto jk = [&](auto f) { return jackknife(R, [&](std::size_t e) { return f(k, e); }); };
        const auto Tr = jackknife(R, [&](std::size_t e) { return pooled[k].v2[slot(e)][j] * mix[k].mass / (pooled[0].v2[slot(e)][j]); });
        const auto Mr = jackknife(R, [&](std::size_t e) { return pooled[k].M[slot(e)][j] / pooled[0].M[slot(e)][j]; });
        const auto c = jk(cumulant);
        // Spread of one replica's MSD estimate (relative standard deviation over replicas).
        double s1 = 0.0, s2 = 0.0;
        for (std::size_t r = 0; r < R; ++r) {
          const double v = run.sum(r, j, k, TaggedRun::r2) / double(counts[k]);
          s1 += v, s2 += v * v;
        }
        const double mean = s1 / double(R), spread = std::sqrt(std::max(0.0, (s2 / double(R) - mean * mean) * double(R) / double(R - 1))) / mean;
        const double ratio_eq17 = eq17[i][k] / M1_th;
        const auto to = jk(T_over), mo = jk(msd_over), mt = jk(msdT_over), me = jk(memory), no = jk(nu_over);
        out.table.rows.push_back({double(N), double(k + 1), double(counts[k]), t[j], Tr.first, Tr.second, h.temperature(t[j], k) / T1_th,
                                  to.first, to.second, Mr.first, Mr.second, ratio_eq17, h.msd_vacf(t[j], k) / M1_vacf, mo.first, mo.second,
                                  mt.first, mt.second, me.first, me.second, no.first, no.second, c.first, c.second, spread,
                                  std::sqrt(2.0 / (3.0 * double(counts[k]))), (Mr.first - ratio_eq17) / Mr.second,
                                  offset(k, 0), sensitivity(k, 0)});
        if (i + 1 == reports.size())
          for (std::size_t r = 0; r < R; ++r)
            replicas.rows.push_back({double(N), double(r), double(k + 1), double(counts[k]), t[j],
                                     run.sum(r, j, k, TaggedRun::r2) / double(counts[k]) / (run.sum(r, j, 0, TaggedRun::r2) / double(counts[0])),
                                     run.sum(r, j, k, TaggedRun::v2) * mix[k].mass / double(counts[k]) /
                                         (run.sum(r, j, 0, TaggedRun::v2) / double(counts[0])),
                                     ratio_eq17});
      }
      const bool report = o.quick || i % 3 == 0;  // t = 1e3, 1e6, 1e9
      for (std::size_t from : {heavy_from, heaviest_from}) {
        const std::size_t to = from == heavy_from ? heaviest_from : S;
        auto mean = [&](auto f, std::size_t e) {  // particle-weighted mean over species [from, to): each particle counts once
          double s = 0.0, w = 0.0;
          for (std::size_t k = from; k < to; ++k) s += double(counts[k]) * f(k, e), w += double(counts[k]);
          return s / w;
        };
        auto part = [&](auto f) { return jackknife(R, [&](std::size_t e) { return mean(f, e); }); };
        auto ratio_of = [&](auto f, auto g) { return jackknife(R, [&](std::size_t e) { return mean(f, e) / mean(g, e); }); };
        // Factors as ratios of group means, so that offset x temperature x memory = MSD/Eq17 exactly.
        const auto gm = part(msd_over), go = part(offset), gt = ratio_of(msdT_over, offset), gme = ratio_of(msd_over, msdT_over);
        const auto gn = part(nu_over);
        const auto gT = part(T_over), gc = part(cumulant), gs = part(sensitivity);
        std::size_t above = 0, below = 0;
        for (std::size_t k = from; k < to; ++k) {
          const double z = out.table.rows[out.table.rows.size() - S + k][out.table.column("z")];
          above += z > 4, below += z < -4;
        }
        out.json.push_back(fmt::format("{{\"case\": \"bo1-fig08\", \"particles\": {}, \"t\": {:g}, \"species_from\": {}, \"species_to\": {}, "
                                       "\"msd_over_eq17\": {:.6g}, \"msd_over_eq17_err\": {:.3g}, \"offset\": {:.6g}, \"temperature\": {:.6g}, "
                                       "\"memory\": {:.6g}, \"memory_err\": {:.3g}, \"nu_eff_over_nu\": {:.6g}, \"nu_eff_over_nu_err\": {:.3g}}}",
                                       N, t[j], from + 1, to, gm.first, gm.second, go.first, gt.first, gme.first, gme.second, gn.first, gn.second));
        if (report)
          out.summary.push_back(fmt::format(
              "bo1-fig08 N = {:g} t = {:g} species {}-{} ({}-{} particles): MSD/Eq17 = {:.3f} +- {:.3f} = offset {:.3f} x temperature {:.3f} "
              "+- {:.3f} x memory {:.3f} +- {:.3f}; nu_eff/nu (last decade) {:.3f} +- {:.3f}, T/T_th {:.3f} +- {:.3f}, c {:.3f} +- {:.3f}, "
              "dlnM/dlnnu {:.1f}; z > 4: {}, z < -4: {} of {}",
              double(N), t[j], from + 1, to, counts[to - 1], counts[from], gm.first, gm.second, go.first, gt.first, gt.second, gme.first,
              gme.second, gn.first, gn.second, gT.first, gT.second, gc.first, gc.second, gs.first, above, below, to - from));
      }
      const auto l1 = jackknife(R, [&](std::size_t e) { return msd_over(0, e); });
      if (report)
        out.summary.push_back(fmt::format("bo1-fig08 N = {:g} t = {:g} species 1: MSD/Eq17 = {:.4f} +- {:.4f}, T/T_th = {:.4f}, c = {:.3f}",
                                          double(N), t[j], l1.first, l1.second, T_over(0, TaggedRun::npos), cumulant(0, TaggedRun::npos)));
    }
  }
  return out;
}

}  // namespace granmix::bench
