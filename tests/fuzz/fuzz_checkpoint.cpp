// libFuzzer harness: bytes of a checkpoint file -> the replica's snapshot or record, or a clear
// InputError naming the file (dsmc/replica_snapshot.cpp, dsmc/replica_run.cpp check_snapshot). Each
// input is read twice: as it is (the checksum refuses nearly every mutation) and with its checksum
// made valid, so that the fuzzer reaches the payload decoder and the consistency checks that stand
// between a file and a resumed run. Any other outcome (crash, other exception, sanitizer report,
// > 2 s) is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "checkpoint_fuzz_runs.hpp"
#include "dsmc/replica_run.hpp"
#include "dsmc/replica_snapshot.hpp"
#include "model/errors.hpp"
#include "model/sha256.hpp"

namespace {

void read_as_every_run(const std::string& bytes) {
  using namespace granmix;
  static const std::vector<dsmc::DsmcSetup> runs = fuzz::checkpoint_runs();
  for (const dsmc::DsmcSetup& s : runs)
    for (std::uint64_t r = 0; r < s.replicas; ++r) {
      const dsmc::SnapshotIdentity id{fuzz::checkpoint_fuzz_version, s.scene_sha256, s.unit_key, r};
      try {
        dsmc::check_snapshot(s, r, dsmc::decode_snapshot(bytes, "fuzz.snap", id), "fuzz.snap");
      } catch (const InputError&) {
      }
      try {
        (void)dsmc::decode_done(bytes, "fuzz.done", id);
      } catch (const InputError&) {
      }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  read_as_every_run(bytes);
  if (bytes.size() > 64) {
    const std::string body = bytes.substr(0, bytes.size() - 64);
    read_as_every_run(body + granmix::model::sha256_hex(body));
  }
  return 0;
}
