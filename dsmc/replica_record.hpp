#pragma once
// Everything one replica of a DSMC set-up records, [time * M + k] (ensemble.hpp reduces the
// replicas to means and errors), and its binary form: how a replica computed on one MPI rank
// reaches the rank that writes the files, and how a finished replica is kept in a checkpoint folder.
// The record of replica r is the same wherever and whenever it is computed (stream (seed, r)), so
// the reduction, done in replica order, gives the same bytes for any number of ranks and threads.
#include <cstdint>
#include <vector>

#include "byte_stream.hpp"

namespace granmix::dsmc {

struct ReplicaRecord {
  std::vector<double> T, msd, cumulant, species_collisions, pair_collisions, rescaled_time, tamsd, distribution;
  std::uint64_t trials = 0, accepted = 0, steps = 0;
  double seconds_setup = 0.0, seconds_loop = 0.0, seconds_sample = 0.0;
};

inline void write_record(ByteWriter& w, const ReplicaRecord& r) {
  for (const auto* v : {&r.T, &r.msd, &r.cumulant, &r.species_collisions, &r.pair_collisions, &r.rescaled_time, &r.tamsd, &r.distribution})
    w.put_vector(*v);
  w.put(r.trials), w.put(r.accepted), w.put(r.steps);
  w.put(r.seconds_setup), w.put(r.seconds_loop), w.put(r.seconds_sample);
}

inline ReplicaRecord read_record(ByteReader& in) {
  ReplicaRecord r;
  for (auto* v : {&r.T, &r.msd, &r.cumulant, &r.species_collisions, &r.pair_collisions, &r.rescaled_time, &r.tamsd, &r.distribution})
    *v = in.get_vector<double>();
  r.trials = in.get<std::uint64_t>(), r.accepted = in.get<std::uint64_t>(), r.steps = in.get<std::uint64_t>();
  r.seconds_setup = in.get<double>(), r.seconds_loop = in.get<double>(), r.seconds_sample = in.get<double>();
  return r;
}

}  // namespace granmix::dsmc
