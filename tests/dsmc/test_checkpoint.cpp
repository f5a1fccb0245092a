// Checkpoint and restart: a replica stopped after any snapshot and resumed from the file
// gives a ReplicaRecord bit-identical to the uninterrupted run (timings aside), for every method, an
// aged start and a TAMSD run; checkpointing itself never changes the trajectory; a finished replica
// is read from its .done file; damaged or foreign files are refused naming the file.
#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include "dsmc/checkpoint_files.hpp"
#include "dsmc/replica_run.hpp"
#include "dsmc_fixtures.hpp"
#include "fresh_dir.hpp"
#include "model/errors.hpp"

using namespace granmix;

namespace {

struct Killed {};  // thrown by the test hook: the replica dies as under SIGKILL, its last snapshot on disk

// Every field of the records but the wall-clock timings, bit for bit.
void require_identical(const dsmc::ReplicaRecord& a, const dsmc::ReplicaRecord& b) {
  auto same = [](const std::vector<double>& x, const std::vector<double>& y) {
    return x.size() == y.size() && (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(double)) == 0);
  };
  CHECK(same(a.T, b.T));
  CHECK(same(a.msd, b.msd));
  CHECK(same(a.cumulant, b.cumulant));
  CHECK(same(a.species_collisions, b.species_collisions));
  CHECK(same(a.pair_collisions, b.pair_collisions));
  CHECK(same(a.rescaled_time, b.rescaled_time));
  CHECK(same(a.tamsd, b.tamsd));
  CHECK(same(a.distribution, b.distribution));
  CHECK(a.trials == b.trials);
  CHECK(a.accepted == b.accepted);
  CHECK(a.steps == b.steps);
}

dsmc::DsmcSetup binary(dsmc::Method m) {
  auto s = test::dsmc_setup({{1, 1, 0.05}, {4, 1.5, 0.05}}, 0.8, {150, 150}, {1.0, 5.0, 20.0, 60.0}, 1, m);
  s.msd = true, s.cumulant = true, s.distribution_bins = 8;
  s.unit_key = "test", s.scene_sha256 = std::string(64, 'a');
  return s;
}

struct Case {
  const char* name;
  dsmc::DsmcSetup setup;
};

std::vector<Case> cases() {
  std::vector<Case> c;
  for (auto m : {dsmc::Method::direct, dsmc::Method::lowrank, dsmc::Method::bird, dsmc::Method::bird_global})
    c.push_back({dsmc::to_string(m), binary(m)});
  auto ts = binary(dsmc::Method::timestep);
  ts.time_step_factor = 0.05, ts.times = {1.0, 3.0, 6.0};
  c.push_back({"timestep", ts});
  auto aged = binary(dsmc::Method::direct);
  aged.aged = true, aged.T0 = {4.0, 4.0};
  c.push_back({"aged", aged});
  auto tamsd = binary(dsmc::Method::direct);
  tamsd.tamsd_measurement_time = 40.0, tamsd.tamsd_lags = {1.0, 5.0}, tamsd.tamsd_tracers = 20, tamsd.times = {1.0, 5.0};
  c.push_back({"tamsd", tamsd});
  return c;
}

}  // namespace

TEST_CASE("restart from any snapshot is bit-identical to the uninterrupted replica", "[dsmc]") {
  for (const Case& k : cases()) {
    INFO(k.name);
    dsmc::DsmcSetup plain = k.setup;
    const dsmc::ReplicaRecord ref = dsmc::run_one_replica(plain, 0);

    // Checkpointing at every refresh point changes nothing, and counts the snapshots of a full run.
    const auto dir = test::fresh_dir(std::string("ckpt-") + k.name);
    dsmc::Checkpointing ck;
    ck.dir = dir, ck.every_seconds = 0.0, ck.granmix_version = "test";
    std::size_t written = 0;
    ck.written = [&](const std::filesystem::path&) { ++written; };
    dsmc::DsmcSetup s = k.setup;
    s.checkpoint = &ck;
    require_identical(dsmc::run_one_replica(s, 0), ref);
    const std::size_t total = written;
    std::printf("checkpoint %s: %zu snapshots in a full run\n", k.name, total);
    REQUIRE(total >= 4);
    CHECK(std::filesystem::exists(dsmc::done_path(s, 0)));
    CHECK_FALSE(std::filesystem::exists(dsmc::snapshot_path(s, 0)));
    // A finished replica is read back, not recomputed (no snapshot written).
    require_identical(dsmc::run_one_replica(s, 0), ref);
    CHECK(written == total);

    // Killed after its first, middle and last snapshot, then resumed from the file.
    for (std::size_t kill_at : {std::size_t(1), total / 2, total}) {
      std::filesystem::remove(dsmc::done_path(s, 0));
      written = 0;
      ck.written = [&](const std::filesystem::path&) {
        if (++written == kill_at) throw Killed{};
      };
      CHECK_THROWS_AS(dsmc::run_one_replica(s, 0), Killed);
      REQUIRE(std::filesystem::exists(dsmc::snapshot_path(s, 0)));
      ck.written = nullptr;
      require_identical(dsmc::run_one_replica(s, 0), ref);
    }
  }
}

TEST_CASE("damaged and foreign checkpoint files are refused naming the file and the reason", "[dsmc]") {
  dsmc::DsmcSetup s = binary(dsmc::Method::direct);
  const auto dir = test::fresh_dir("ckpt-refusals");
  dsmc::Checkpointing ck;
  ck.dir = dir, ck.every_seconds = 0.0, ck.granmix_version = "test";
  ck.written = [](const std::filesystem::path&) { throw Killed{}; };
  s.checkpoint = &ck;
  CHECK_THROWS_AS(dsmc::run_one_replica(s, 0), Killed);
  ck.written = nullptr;
  const auto snap = dsmc::snapshot_path(s, 0);
  std::ifstream in(snap, std::ios::binary);
  const std::string good((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto refused = [&](const std::string& bytes, const std::string& why) {
    INFO(why);
    { std::ofstream(snap, std::ios::binary) << bytes; }
    try {
      dsmc::verify_checkpoint_folder(ck, {s});
      FAIL("accepted");
    } catch (const InputError& e) {
      const std::string m = e.what();
      INFO(m);
      CHECK(m.find(snap.string()) != std::string::npos);
      CHECK(m.find(why) != std::string::npos);
    }
    CHECK_THROWS_AS(dsmc::run_one_replica(s, 0), InputError);  // the run itself refuses too
  };
  std::string flipped = good;
  flipped[flipped.size() / 2] ^= 0x10;
  refused(flipped, "checksum");
  refused(good.substr(0, good.size() - 100), "checksum");
  refused(good.substr(0, 12), "truncated");
  std::string swapped = good;
  std::swap(swapped[12], swapped[15]), std::swap(swapped[13], swapped[14]);
  refused(swapped, "other byte order");
  refused("hello", "not a granmix checkpoint");
  std::string format1 = good;  // a file of format 1 (no float intercepts, epoch not stored)
  format1[8] = 1, format1[9] = format1[10] = format1[11] = 0;
  refused(format1, "checkpoint format 1, this granmix reads format 2");
  // Another version and another scene: valid files of another identity.
  dsmc::SnapshotIdentity id = dsmc::snapshot_identity(ck, s, 0);
  dsmc::ReplicaSnapshot x = dsmc::decode_snapshot(good, "f", id);
  id.granmix_version = "0.0.9 (old)";
  refused(dsmc::encode_snapshot(id, x), "written by granmix 0.0.9");
  id = dsmc::snapshot_identity(ck, s, 0), id.scene_sha256 = std::string(64, 'b');
  refused(dsmc::encode_snapshot(id, x), "another scene");
  // A valid file that does not fit the run: an epoch that is not finite; one sample too few for its stop.
  id = dsmc::snapshot_identity(ck, s, 0);
  x.particles.epoch = std::numeric_limits<double>::quiet_NaN();
  refused(dsmc::encode_snapshot(id, x), "not finite");
  x.particles.epoch = 0.0;
  x.record.T.push_back(1.0);
  refused(dsmc::encode_snapshot(id, x), "samples taken so far");
  // A file of a unit the run does not plan.
  std::filesystem::remove(snap);
  { std::ofstream(dir / "other-scene.quick.seed1.abc.r0.snap") << good; }
  CHECK_THROWS_WITH(dsmc::verify_checkpoint_folder(ck, {s}), Catch::Contains("a snapshot of another scene or run"));
}
