#pragma once
// The one place MPI lives (docs/user-guide.md, "Cluster scale"). A command's DSMC work is cut into units — one replica of one
// ensemble (a scene, or one point of a sweep) — listed identically on every rank, sorted longest
// first by their estimated collisions (dsmc/unit_cost.hpp), and handed out one at a time by rank 0 to
// whichever thread of whichever rank asks next. Rank 0 gathers every record; the command then builds
// its tables and writes every file on rank 0 alone, taking the replicas from the gathered set.
// Replica r of an ensemble always draws from stream (seed, r) and the reduction runs in replica order,
// so every output is bit-identical for any number of ranks and threads. One replica is never split:
// it is one Markov chain (its wall time bounds the makespan; see `granmix bench schedule`).
//
// Without MPI (a build with GRANMIX_MPI=OFF, or a process not started by an MPI launcher) the same
// code runs with one rank: the units go to this process's threads, longest first.
#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "dsmc/ensemble.hpp"

namespace granmix::compare::scheduler {

// This process's rank and the number of ranks: 0 and 1 unless an MPI build was started by an MPI
// launcher (mpirun, mpiexec, srun: detected from the environment it sets), in which case MPI is
// initialised on the first call. Call after interrupts::install(): MPI starts threads, and they must
// inherit the blocked signals.
int rank();
int ranks();
inline bool root() { return rank() == 0; }
// --threads 0 under MPI: this node's cores shared among its ranks (OMPI_COMM_WORLD_LOCAL_SIZE).
int threads_per_rank(int requested);

// One finished unit: what it was estimated to cost and what it cost (collisions; CPU seconds of the
// thread that ran it, which do not grow when the machine is shared).
struct UnitCost {
  std::string key;
  std::size_t replica = 0;
  double estimated_collisions = 0.0, collisions = 0.0, seconds = 0.0;
  int rank = 0;
};

// The records of every unit, found by (unit key, replica): rank 0's source for run_ensemble.
class GatheredReplicas : public dsmc::ReplicaSource {
 public:
  const dsmc::ReplicaRecord* find(const std::string& unit_key, std::size_t replica) const override;
  std::map<std::pair<std::string, std::size_t>, dsmc::ReplicaRecord> records;
  std::vector<UnitCost> units;  // in the order they were handed out (longest estimate first)
  double cpu_seconds = 0.0;     // CPU seconds summed over units
  double wall_seconds = 0.0;
  int ranks = 1, threads = 1;   // threads per rank
};

// Every replica of every set-up over all ranks with `threads` threads each (0: threads_per_rank).
// Returns the records on rank 0 and an empty set on the others, which then write nothing. A unit
// that fails stops the run with its error (rank and unit named). Progress on stderr (rank 0).
GatheredReplicas run_units(const std::vector<dsmc::DsmcSetup>& setups, int threads);

// Rank 0's text on every rank (a decision only rank 0 can make, e.g. which scenes validate confirms); without
// MPI, the text itself.
std::string share_from_root(const std::string& text);

// MPI_Finalize if MPI was initialised; main calls it after the command.
void finish();
// After an error: with several ranks, MPI_Abort with the exit code (the others may be waiting on this
// one); otherwise finish().
void abort(int code);

}  // namespace granmix::compare::scheduler
