#include "checkpoint_files.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <thread>

#include "model/errors.hpp"
#include "replica_run.hpp"

namespace granmix::dsmc {

namespace {

std::filesystem::path unit_file(const DsmcSetup& s, std::size_t r, const char* ext) {
  return s.checkpoint->dir / (s.unit_key + ".r" + std::to_string(r) + ext);
}

std::string os_error() { return std::strerror(errno); }

}  // namespace

std::filesystem::path snapshot_path(const DsmcSetup& s, std::size_t r) { return unit_file(s, r, ".snap"); }
std::filesystem::path done_path(const DsmcSetup& s, std::size_t r) { return unit_file(s, r, ".done"); }

SnapshotIdentity snapshot_identity(const Checkpointing& c, const DsmcSetup& s, std::size_t r) {
  return {c.granmix_version, s.scene_sha256, s.unit_key, r};
}

std::optional<std::string> read_checkpoint_file(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return std::nullopt;
  std::ifstream in(file, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) throw InputError(file.string() + ": cannot read the checkpoint file");
  return bytes;
}

void write_checkpoint_file(const std::filesystem::path& file, const std::string& bytes) {
  // Hidden, per process and thread: replicas of one run write their own files concurrently.
  std::string name = ".";
  name += file.filename().string();
  name += ".tmp-" + std::to_string(getpid()) + "-" + std::to_string(std::hash<std::thread::id>{}(std::this_thread::get_id()));
  const std::filesystem::path tmp = file.parent_path() / name;
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (f == nullptr) throw InputError(tmp.string() + ": cannot write a checkpoint: " + os_error());
  const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size() && std::fflush(f) == 0 && fsync(fileno(f)) == 0;
  const std::string why = os_error();
  if (std::fclose(f) != 0 || !ok) {
    std::remove(tmp.c_str());
    throw InputError(tmp.string() + ": cannot write a checkpoint: " + why + " (disk full?)");
  }
  if (std::rename(tmp.c_str(), file.c_str()) != 0) {
    const std::string e = os_error();
    std::remove(tmp.c_str());
    throw InputError(file.string() + ": cannot rename the checkpoint into place: " + e);
  }
}

void prepare_checkpoint_folder(const Checkpointing& c, bool must_exist) {
  std::error_code ec;
  const std::string flag = must_exist ? "--restart " : "--checkpoint ";
  if (must_exist && !std::filesystem::is_directory(c.dir, ec))
    throw InputError(flag + c.dir.string() + ": no such folder (allowed: the checkpoint folder of an earlier run)");
  std::filesystem::create_directories(c.dir, ec);
  if (ec || !std::filesystem::is_directory(c.dir))
    throw InputError(flag + c.dir.string() + ": cannot create the folder" + (ec ? ": " + ec.message() : "") + " (allowed: a writable folder)");
  try {
    const std::filesystem::path probe = c.dir / (".granmix-probe-" + std::to_string(getpid()));
    write_checkpoint_file(probe, "x");
    std::filesystem::remove(probe, ec);
  } catch (const InputError& e) {
    throw InputError(flag + c.dir.string() + ": cannot write in the folder (allowed: a writable folder): " + e.what());
  }
}

void verify_checkpoint_folder(const Checkpointing& c, const std::vector<DsmcSetup>& plan) {
  std::map<std::string, const DsmcSetup*> units;
  for (const DsmcSetup& s : plan)
    if (!s.unit_key.empty()) units[s.unit_key] = &s;
  std::error_code ec;
  if (!std::filesystem::is_directory(c.dir, ec)) return;
  for (const auto& e : std::filesystem::directory_iterator(c.dir)) {
    const std::string name = e.path().filename().string(), file = e.path().string();
    if (name.empty() || name[0] == '.') continue;
    const std::string ext = e.path().extension().string(), stem = e.path().stem().string();  // <key>.r<r>
    const std::size_t dot = stem.rfind(".r");
    if (!e.is_regular_file() || (ext != ".snap" && ext != ".done") || dot == std::string::npos)
      throw InputError(file + ": not a checkpoint file of granmix (allowed in a checkpoint folder: <run>.r<replica>.snap or .done)");
    const std::string key = stem.substr(0, dot), index = stem.substr(dot + 2);
    const auto it = units.find(key);
    const bool numeric = !index.empty() && index.size() < 19 && index.find_first_not_of("0123456789") == std::string::npos;
    if (it == units.end() || !numeric || std::stoull(index) >= it->second->replicas)
      throw InputError(file + ": a snapshot of another scene or run (" + key + " replica " + index +
                       " is not planned here; allowed: the checkpoint folder of this command with the same scenes, fidelity and seed)");
    const DsmcSetup& s = *it->second;
    const std::size_t r = std::stoull(index);
    const std::optional<std::string> read = read_checkpoint_file(e.path());
    if (!read)  // listed a moment ago: a run still alive renamed or removed it
      throw InputError(file + ": vanished while the checkpoint folder was read (allowed: a folder no running granmix writes in)");
    const std::string& bytes = *read;
    if (ext == ".done") {
      (void)decode_done(bytes, file, snapshot_identity(c, s, r));
    } else {
      check_snapshot(s, r, decode_snapshot(bytes, file, snapshot_identity(c, s, r)), file);
    }
  }
}

}  // namespace granmix::dsmc
