// Writes the seed corpus of the checkpoint harness: every snapshot and the finished record of the
// tiny runs of checkpoint_fuzz_runs.hpp, checkpointed at every refresh point or step.
// Usage: make_checkpoint_corpus DIR. The committed tests/fuzz/corpus/checkpoint is its output merged
// (-merge=1) with what 31 min of fuzzing found.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "checkpoint_fuzz_runs.hpp"
#include "dsmc/checkpoint_files.hpp"

int main(int argc, char** argv) {
  using namespace granmix;
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_checkpoint_corpus DIR\n");
    return 2;
  }
  const std::filesystem::path out = argv[1], work = out / ".work";
  std::filesystem::create_directories(work);
  dsmc::Checkpointing ck;
  ck.dir = work, ck.every_seconds = 0.0, ck.granmix_version = fuzz::checkpoint_fuzz_version;
  std::size_t n = 0;
  ck.written = [&](const std::filesystem::path& p) {
    if (n % 7 == 0) std::filesystem::copy_file(p, out / ("snap-" + std::to_string(n)), std::filesystem::copy_options::overwrite_existing);
    ++n;
  };
  for (dsmc::DsmcSetup s : fuzz::checkpoint_runs()) {
    s.checkpoint = &ck;
    (void)dsmc::run_ensemble(s);
    for (std::size_t r = 0; r < s.replicas; ++r)
      std::filesystem::copy_file(dsmc::done_path(s, r), out / (s.unit_key + ".r" + std::to_string(r) + ".done"),
                                 std::filesystem::copy_options::overwrite_existing);
  }
  std::filesystem::remove_all(work);
  std::printf("%zu snapshots written, every 7th kept\n", n);
  return 0;
}
