#pragma once
// The checkpoint folder of a run: <dir>/<unit_key>.r<r>.snap, the latest snapshot of
// replica r in flight, and <dir>/<unit_key>.r<r>.done, its record once finished (the .snap is then
// removed). Files are written atomically (a hidden temporary in the same folder, then rename), so a
// kill leaves either the previous file or the new one.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ensemble.hpp"
#include "replica_snapshot.hpp"

namespace granmix::dsmc {

std::filesystem::path snapshot_path(const DsmcSetup& s, std::size_t r);
std::filesystem::path done_path(const DsmcSetup& s, std::size_t r);
// Who writes replica r of a set-up into the folder c.
SnapshotIdentity snapshot_identity(const Checkpointing& c, const DsmcSetup& s, std::size_t r);

// The whole file, or nothing if it does not exist; InputError if it cannot be read.
std::optional<std::string> read_checkpoint_file(const std::filesystem::path& file);
// InputError naming the file if it cannot be written (a full disk, a read-only folder).
void write_checkpoint_file(const std::filesystem::path& file, const std::string& bytes);

// Exit 2 (InputError naming the folder) unless it is, or can be created as, a writable folder;
// with must_exist (--restart), unless it exists.
void prepare_checkpoint_folder(const Checkpointing& c, bool must_exist);

// Every file of the checkpoint folder checked against the planned set-ups before anything is
// computed or written: a file of a unit not in the plan, of another version or scene, of the other
// byte order, truncated or corrupt is refused (InputError naming the file). Hidden files (the
// temporaries a kill left) are ignored.
void verify_checkpoint_folder(const Checkpointing& c, const std::vector<DsmcSetup>& plan);

}  // namespace granmix::dsmc
