// Study `gaps`: measures in the exact DSMC what the papers' theory assumes, to put
// the gaps between them down to named causes with numbers (docs/validation.md, "Why theory and DSMC differ").
//   gaps.tsv           bo1-fig02: T_k, c_k, Q_k = ⟨R·v⟩, ν_eff against ν_k, D/D[1], MSD variants
//   gaps_fig08.tsv     bo1-fig08 at N = 5e4, 1e5, 2e5: per (N, t, species) T, MSD ratio and their factors
//   gaps_replicas.tsv  bo1-fig08 at the last time: one row per (N, replica, species)
//   gaps_znull.tsv     the scene's z-score for species of n particles over R replicas under the null
//   gaps_cumulant.tsv  v1 Figs. 2, 9, 10: T_k and c_k of DSMC and of the kinetic level, and T_k from the
//                      first-Sonine rates driven by the measured c_k(t) (gaps_cumulant.cpp)
// The figure: DSMC MSD over Eq. 17 for bo1-fig02's species, and the light species' MSD rebuilt from
// measured inputs step by step (gaps_light.cpp), over Eq. 17.
#include <fmt/format.h>

#include "gaps_parts.hpp"
#include "replica_z_null.hpp"

namespace granmix::bench {

StudyResult gaps_study(const StudyOptions& o) {
  StudyResult out;
  out.name = "gaps";
  GapsPart light = light_gaps(o);
  out.table = std::move(light.table);
  out.summary = std::move(light.summary);
  out.json = std::move(light.json);
  out.figure = {"t", "msd_over_eq17", "t", "MSD / v1 Eq. (17)", true, false, {"DSMC light (m = 1)", "DSMC heavy (m = 100)"}, {}};
  const char* rebuilt[][2] = {{"msd_vacf", "VACF form (first Sonine)"},
                              {"msd_T", "+ measured T_k(t)"},
                              {"msd_T_D2", "+ measured late D/D[1]"},
                              {"msd_memory", "+ measured nu_eff(t)"}};
  for (std::size_t i = 0; i < 4; ++i)
    out.figure.extra.push_back(fmt::format("'gaps.tsv' using (column('series') == 0 ? column('t') : NaN):(column('{}')/column('msd_eq17')) "
                                           "with lines lw 2 dt {} title 'light: {}'",
                                           rebuilt[i][0], i + 2, rebuilt[i][1]));
  model::Table replicas;
  GapsPart heavy = heavy_gaps(o, replicas);
  out.summary.insert(out.summary.end(), heavy.summary.begin(), heavy.summary.end());
  out.json.insert(out.json.end(), heavy.json.begin(), heavy.json.end());
  out.tables.push_back({"gaps_fig08", std::move(heavy.table)});
  out.tables.push_back({"gaps_replicas", std::move(replicas)});
  model::Table z;
  z.columns = {"particles", "replicas", "trials", "z_q005", "z_q025", "z_median", "z_q975", "z_q995", "p_above4", "p_below4", "spread"};
  for (std::size_t R : {4, 8, 16})
    for (std::size_t n : {1, 2, 5, 10, 40}) {
      const ZNull q = z_null(n, R, o.quick ? 2000 : 40000, o.seed);
      z.rows.push_back({double(n), double(R), double(q.trials), q.q005, q.q025, q.q50, q.q975, q.q995, q.p_above4, q.p_below4, q.spread});
      if (R == 8 && (n == 1 || n == 40))
        out.summary.push_back(fmt::format("null z of a species of {} particle(s) over {} replicas: 95% in [{:.2f}, {:.2f}], 99% in [{:.2f}, {:.2f}], "
                                          "P(z > 4) = {:.4f}, P(z < -4) = {:.4f}",
                                          n, R, q.q025, q.q975, q.q005, q.q995, q.p_above4, q.p_below4));
    }
  out.tables.push_back({"gaps_znull", std::move(z)});
  GapsPart cumulant = cumulant_gaps(o);
  out.summary.insert(out.summary.end(), cumulant.summary.begin(), cumulant.summary.end());
  out.json.insert(out.json.end(), cumulant.json.begin(), cumulant.json.end());
  out.tables.push_back({"gaps_cumulant", std::move(cumulant.table)});
  return out;
}

}  // namespace granmix::bench
