#pragma once
// One replica of a DSMC set-up, from its start or from a snapshot, to its record (ensemble.cpp runs
// them in threads and reduces them). With set-up.checkpoint (and a unit key) a finished replica's
// record is read from its .done file, one in flight resumes from its .snap, and the replica writes
// snapshots as it goes (dsmc/checkpoint_files.hpp); the record is bit-identical either way (the
// seconds_* timings aside).
#include <string>

#include "ensemble.hpp"
#include "pair_table.hpp"
#include "replica_snapshot.hpp"

namespace granmix::dsmc {

// automatic: direct up to 8 species, low-rank above.
Method resolved_method(const DsmcSetup& s);

ReplicaRecord run_replica(const DsmcSetup& s, const PairTable& pairs, std::size_t r);

// InputError naming `file` unless the snapshot fits the set-up exactly (particle counts and masses,
// record sizes for its stop, TAMSD accumulators, the random stream of replica r, finite numbers): a snapshot
// that passes is resumed without any further check.
void check_snapshot(const DsmcSetup& s, std::size_t r, const ReplicaSnapshot& snapshot, const std::string& file);

}  // namespace granmix::dsmc
