// Study `checkpoint`: what a snapshot of a replica in flight costs. For a one-species gas
// of N particles, with and without displacements: the file's bytes, the seconds to encode and write
// it (temp file, fsync, rename), and to read, check and decode it, per 10⁶ particles. Then the
// overhead on a run: a replica of a direct binary run without checkpointing, with checkpointing on
// but never due (the clock read at each refresh point), and the cost of one snapshot per 60 s.
#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <unistd.h>

#include "dsmc/checkpoint_files.hpp"
#include "dsmc/replica_run.hpp"
#include "study.hpp"

namespace granmix::bench {

namespace {

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

dsmc::DsmcSetup gas(std::size_t N, bool displacement, std::uint64_t seed) {
  dsmc::DsmcSetup s;
  s.mixture = model::Mixture({{1, 1, 0.1}});
  s.law = model::Restitution::constant(1, 0.9);
  s.counts = {N}, s.T0 = {1.0}, s.times = {1.0}, s.msd = displacement, s.seed = seed;
  s.unit_key = "bench", s.scene_sha256 = std::string(64, '0');
  return s;
}

}  // namespace

StudyResult checkpoint_study(const StudyOptions& o) {
  StudyResult out;
  out.name = "checkpoint";
  out.table.columns = {"series", "particles", "bytes", "write_seconds", "read_seconds", "bytes_per_1e6", "write_seconds_per_1e6",
                       "read_seconds_per_1e6"};
  out.figure = {"particles", "write_seconds", "particles", "seconds to write one snapshot", true, true,
                {"velocities only", "with displacements"}, {}};
  const auto dir = std::filesystem::temp_directory_path() / ("granmix-bench-checkpoint-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  dsmc::Checkpointing ck;
  ck.dir = dir, ck.granmix_version = "bench";
  const std::vector<std::size_t> sizes = o.quick ? std::vector<std::size_t>{10000, 100000} : std::vector<std::size_t>{100000, 1000000, 4000000};
  for (int displacement = 0; displacement < 2; ++displacement)
    for (std::size_t N : sizes) {
      dsmc::DsmcSetup s = gas(N, displacement, o.seed);
      s.checkpoint = &ck;
      dsmc::Rng rng(s.seed, 0);
      dsmc::ReplicaSnapshot x;
      x.particles = dsmc::maxwellian_particles(s.mixture, s.counts, s.T0, s.msd, s.rescale, rng);
      x.rng = rng.state(), x.loop.e1_start = 1.0;
      x.counters.species_collisions = {0}, x.counters.pair_collisions = {0};
      double write = 1e300, read = 1e300;
      std::size_t bytes = 0;
      const auto file = dsmc::snapshot_path(s, 0);
      for (int rep = 0; rep < o.repeats; ++rep) {  // the fastest of the repeats: the machine is shared
        auto t0 = std::chrono::steady_clock::now();
        const std::string b = dsmc::encode_snapshot(dsmc::snapshot_identity(ck, s, 0), x);
        dsmc::write_checkpoint_file(file, b);
        write = std::min(write, since(t0));
        bytes = b.size();
        t0 = std::chrono::steady_clock::now();
        const auto back = dsmc::read_checkpoint_file(file);
        dsmc::check_snapshot(s, 0, dsmc::decode_snapshot(*back, file.string(), dsmc::snapshot_identity(ck, s, 0)), file.string());
        read = std::min(read, since(t0));
      }
      std::filesystem::remove(file);
      const double per = 1e6 / double(N);
      out.table.rows.push_back({double(displacement), double(N), double(bytes), write, read, bytes * per, write * per, read * per});
      out.summary.push_back(fmt::format("N = {:>8}, {}: {:.1f} MB, write {:.3f} s, read+check {:.3f} s; per 1e6 particles {:.1f} MB, {:.3f} s, {:.3f} s", N,
                                        displacement ? "with displacements" : "velocities only   ", bytes / 1e6, write, read,
                                        bytes * per / 1e6, write * per, read * per));
      out.json.push_back(fmt::format("{{\"particles\": {}, \"displacements\": {}, \"bytes\": {}, \"write_seconds\": {:.4g}, \"read_seconds\": {:.4g}}}", N,
                                     displacement ? "true" : "false", bytes, write, read));
    }
  // Overhead on a run: the same replica without checkpointing and with it on but never due.
  dsmc::DsmcSetup run = gas(o.quick ? 20000 : 200000, true, o.seed);
  run.mixture = model::Mixture({{1, 1, 0.1}, {4, 1.5, 0.1}}), run.law = model::Restitution::constant(2, 0.9);
  run.counts = {run.counts[0] / 2, run.counts[0] / 2}, run.T0 = {1.0, 1.0}, run.times = {o.quick ? 5.0 : 20.0};
  const dsmc::PairTable pairs(run.mixture, {}, double(run.counts[0] + run.counts[1]) / run.mixture.total_density());
  auto timed = [&](const dsmc::Checkpointing* c) {
    double best = 1e300;
    for (int rep = 0; rep < o.repeats; ++rep) {
      std::filesystem::remove(dir / "bench.r0.done");
      dsmc::DsmcSetup x = run;
      x.checkpoint = c;
      const auto t0 = std::chrono::steady_clock::now();
      (void)dsmc::run_replica(x, pairs, 0);
      best = std::min(best, since(t0));
    }
    return best;
  };
  dsmc::Checkpointing never = ck;
  never.every_seconds = 1e9;
  const double off = timed(nullptr), polled = timed(&never);
  const double snapshot_1e6 = out.table.rows.back()[6];  // write seconds per 1e6 particles with displacements
  const double N = double(run.counts[0] + run.counts[1]);
  out.summary.push_back(fmt::format("run of {} particles: {:.3f} s without checkpointing, {:.3f} s with it on but never due ({:+.2f}%)", N, off,
                                    polled, 100.0 * (polled / off - 1.0)));
  out.summary.push_back(fmt::format("every 60 s on a 1-minute run of 1e6 particles: one snapshot, {:.3f} s = {:.2f}% of the run", snapshot_1e6,
                                    100.0 * snapshot_1e6 / 60.0));
  out.json.push_back(fmt::format("{{\"run_particles\": {}, \"seconds_off\": {:.4g}, \"seconds_polled\": {:.4g}}}", N, off, polled));
  std::filesystem::remove_all(dir);
  return out;
}

}  // namespace granmix::bench
