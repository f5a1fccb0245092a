#include "replica_snapshot.hpp"

#include <cstring>

#include "byte_stream.hpp"
#include "model/errors.hpp"
#include "model/sha256.hpp"

namespace granmix::dsmc {

namespace {

constexpr std::uint32_t format_version = 2, endian_tag = 0x01020304;
constexpr std::size_t magic_size = 8, checksum_size = 64;

std::string magic(SnapshotKind kind) { return std::string("GRANMIX") + static_cast<char>(kind); }

std::string frame(SnapshotKind kind, const SnapshotIdentity& id, const std::string& payload) {
  ByteWriter w;
  for (char c : magic(kind)) w.put(c);
  w.put(format_version), w.put(endian_tag);
  w.put_string(id.granmix_version), w.put_string(id.scene_sha256), w.put_string(id.unit_key), w.put(id.replica);
  std::string bytes = w.take() + payload;
  return bytes + model::sha256_hex(bytes);
}

[[noreturn]] void refuse(const std::string& file, const std::string& why) {
  throw InputError(file + ": " + why + " (allowed: a checkpoint of this run written by this granmix; remove the file or the folder to start afresh)");
}

// Checks magic, format, byte order and checksum; returns a reader positioned after the identity.
ByteReader open(std::string_view bytes, const std::string& file, SnapshotKind kind, SnapshotIdentity& id) {
  const std::string want = magic(kind);
  if (bytes.size() < magic_size || bytes.substr(0, magic_size) != want) {
    const std::string_view other = bytes.substr(0, std::min(bytes.size(), magic_size));
    if (other.substr(0, 7) == "GRANMIX" && other.size() == magic_size)
      refuse(file, std::string("a ") + (other[7] == 'S' ? "snapshot of a replica in flight" : "finished replica") + " where a " +
                       (kind == SnapshotKind::in_flight ? "snapshot" : "finished replica") + " was expected");
    refuse(file, "not a granmix checkpoint file (no GRANMIX magic)");
  }
  if (bytes.size() < magic_size + 8 + checksum_size) refuse(file, "truncated (" + std::to_string(bytes.size()) + " bytes)");
  std::uint32_t version = 0, tag = 0;
  std::memcpy(&version, bytes.data() + magic_size, 4);
  std::memcpy(&tag, bytes.data() + magic_size + 4, 4);
  if (tag != endian_tag) {
    if (tag == __builtin_bswap32(endian_tag)) refuse(file, "written on a machine of the other byte order");
    refuse(file, "corrupt header (unknown byte-order tag)");
  }
  if (version != format_version)
    refuse(file, "checkpoint format " + std::to_string(version) + ", this granmix reads format " + std::to_string(format_version));
  const std::string_view body = bytes.substr(0, bytes.size() - checksum_size);
  if (model::sha256_hex(body) != bytes.substr(body.size())) refuse(file, "truncated or corrupt (checksum mismatch)");
  ByteReader in(body);
  try {
    for (std::size_t i = 0; i < magic_size + 8; ++i) (void)in.get<char>();
    id.granmix_version = in.get_string(), id.scene_sha256 = in.get_string(), id.unit_key = in.get_string();
    id.replica = in.get<std::uint64_t>();
  } catch (const std::runtime_error& e) {
    refuse(file, std::string("corrupt identity: ") + e.what());
  }
  return in;
}

void require(const SnapshotIdentity& id, const SnapshotIdentity& want, const std::string& file) {
  if (id.granmix_version != want.granmix_version)
    refuse(file, "written by granmix " + id.granmix_version + ", this is granmix " + want.granmix_version +
                     " (a restart is bit-identical only with the same build)");
  if (id.scene_sha256 != want.scene_sha256) refuse(file, "a snapshot of another scene (SHA-256 " + id.scene_sha256.substr(0, 12) + ", this scene " + want.scene_sha256.substr(0, 12) + ")");
  if (id.unit_key != want.unit_key) refuse(file, "a snapshot of another run (" + id.unit_key + ", this run " + want.unit_key + ")");
  if (id.replica != want.replica)
    refuse(file, "holds replica " + std::to_string(id.replica) + ", its name says replica " + std::to_string(want.replica));
}

template <class F>
auto payload(std::string_view bytes, const std::string& file, SnapshotKind kind, const SnapshotIdentity& expected, F read) {
  SnapshotIdentity id;
  ByteReader in = open(bytes, file, kind, id);
  require(id, expected, file);
  try {
    auto out = read(in);
    if (!in.done()) refuse(file, "corrupt: " + std::to_string(bytes.size() - checksum_size - in.position()) + " bytes after the payload");
    return out;
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const InputError*>(&e)) throw;
    refuse(file, std::string("corrupt payload: ") + e.what());
  }
}

void put_counters(ByteWriter& w, const Counters& c) {
  w.put(c.trials), w.put(c.accepted), w.put(c.refreshes);
  w.put_vector(c.species_collisions), w.put_vector(c.pair_collisions);
}

Counters get_counters(ByteReader& in) {
  Counters c;
  c.trials = in.get<std::uint64_t>(), c.accepted = in.get<std::uint64_t>(), c.refreshes = in.get<std::uint64_t>();
  c.species_collisions = in.get_vector<std::uint64_t>(), c.pair_collisions = in.get_vector<std::uint64_t>();
  return c;
}

}  // namespace

std::string encode_snapshot(const SnapshotIdentity& id, const ReplicaSnapshot& s) {
  ByteWriter w;
  w.put<std::uint8_t>(s.aging), w.put(s.stop);
  const Particles& p = s.particles;
  w.put_vector(p.offset), w.put_vector(p.mass), w.put_vector(p.v), w.put<std::uint8_t>(p.track_displacement), w.put(p.epoch);
  w.put_vector(p.flight);
  w.put_string(s.rng);
  w.put(s.loop.t), w.put(s.loop.ts), w.put(s.loop.t_e1), w.put(s.loop.e1_start), w.put(s.loop.steps), w.put_vector(s.loop.carry);
  put_counters(w, s.counters);
  write_record(w, s.record);
  w.put<std::uint64_t>(s.tamsd_start.size());
  for (const auto& v : s.tamsd_start) w.put_vector(v);
  w.put_vector(s.tamsd_sum), w.put_vector(s.tamsd_weight);
  return frame(SnapshotKind::in_flight, id, w.take());
}

std::string encode_done(const SnapshotIdentity& id, const ReplicaRecord& r) {
  ByteWriter w;
  write_record(w, r);
  return frame(SnapshotKind::done, id, w.take());
}

SnapshotIdentity read_identity(std::string_view bytes, const std::string& file, SnapshotKind kind) {
  SnapshotIdentity id;
  (void)open(bytes, file, kind, id);
  return id;
}

ReplicaSnapshot decode_snapshot(std::string_view bytes, const std::string& file, const SnapshotIdentity& expected) {
  return payload(bytes, file, SnapshotKind::in_flight, expected, [](ByteReader& in) {
    ReplicaSnapshot s;
    s.aging = in.get<std::uint8_t>() != 0, s.stop = in.get<std::uint64_t>();
    Particles& p = s.particles;
    p.offset = in.get_vector<std::size_t>(), p.mass = in.get_vector<double>(), p.v = in.get_vector<Vec3>();
    p.track_displacement = in.get<std::uint8_t>() != 0, p.epoch = in.get<double>(), p.flight = in.get_vector<Vec3f>();
    s.rng = in.get_string();
    s.loop.t = in.get<double>(), s.loop.ts = in.get<double>(), s.loop.t_e1 = in.get<double>(), s.loop.e1_start = in.get<double>();
    s.loop.steps = in.get<std::uint64_t>(), s.loop.carry = in.get_vector<double>();
    s.counters = get_counters(in);
    s.record = read_record(in);
    const auto starts = in.get<std::uint64_t>();
    if (starts > in.remaining() / 8) throw std::runtime_error("more TAMSD starts than bytes left");
    s.tamsd_start.resize(starts);
    for (auto& v : s.tamsd_start) v = in.get_vector<Vec3>();
    s.tamsd_sum = in.get_vector<double>(), s.tamsd_weight = in.get_vector<double>();
    return s;
  });
}

ReplicaRecord decode_done(std::string_view bytes, const std::string& file, const SnapshotIdentity& expected) {
  return payload(bytes, file, SnapshotKind::done, expected, [](ByteReader& in) { return read_record(in); });
}

}  // namespace granmix::dsmc
