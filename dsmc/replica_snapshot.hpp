#pragma once
// The checkpoint files of one replica, in a versioned, endian-tagged binary form:
//   magic (8 bytes: "GRANMIXS" snapshot of a replica in flight, "GRANMIXD" finished replica),
//   format version (u32), endian tag (u32 0x01020304 as written), then the identity (granmix
//   version, scene SHA-256, unit key, replica index), the payload, and the SHA-256 of all bytes
//   before it (64 hex digits). A snapshot's payload is the replica's whole state at a refresh point
//   (dsmc/loop_state.hpp): particles, random stream, loop scalars, counters, the samples taken so far
//   and the TAMSD accumulators; a finished replica's payload is its ReplicaRecord.
// Decoding refuses, naming the file and what is wrong: another format, the other byte order, a
// truncated or corrupt file (checksum), another granmix version, scene, run or replica.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "event_loop.hpp"
#include "loop_state.hpp"
#include "particles.hpp"
#include "replica_record.hpp"

namespace granmix::dsmc {

// Whose file it is: checked against the run that reads it.
struct SnapshotIdentity {
  std::string granmix_version, scene_sha256, unit_key;
  std::uint64_t replica = 0;
};

struct ReplicaSnapshot {
  bool aging = false;        // in the aged start's cooling phase (before the measurement clock starts)
  std::uint64_t stop = 0;    // index of the stop (sample or TAMSD time) the replica was running to
  Particles particles;
  std::string rng;           // Rng::state()
  LoopState loop;
  Counters counters;
  ReplicaRecord record;      // samples up to `stop`
  std::vector<std::vector<Vec3>> tamsd_start;  // tracer positions at each TAMSD start passed (else empty)
  std::vector<double> tamsd_sum, tamsd_weight; // [lag * M + k]
};

enum class SnapshotKind : char { in_flight = 'S', done = 'D' };

std::string encode_snapshot(const SnapshotIdentity& id, const ReplicaSnapshot& s);
std::string encode_done(const SnapshotIdentity& id, const ReplicaRecord& r);

// The identity a file claims (after the magic, format, byte order and checksum are checked): used to
// tell a file of another run from a corrupt one. Throws InputError naming `file`.
SnapshotIdentity read_identity(std::string_view bytes, const std::string& file, SnapshotKind kind);

// The payload, after every check of read_identity and that the identity is `expected`. The
// snapshot's consistency with the set-up is checked by the runner (dsmc/replica_run.hpp).
ReplicaSnapshot decode_snapshot(std::string_view bytes, const std::string& file, const SnapshotIdentity& expected);
ReplicaRecord decode_done(std::string_view bytes, const std::string& file, const SnapshotIdentity& expected);

}  // namespace granmix::dsmc
