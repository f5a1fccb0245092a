#pragma once
// Outputs that cannot mix (docs/user-guide.md, "Output files"): DIR/<scene>/ holds the outputs of one scene file.
// theory, dsmc and compare write there; when the folder already holds tables whose provenance names another scene
// SHA-256 (the scene file was edited, or another file has the same [scene] name), the old folder is moved aside to
// DIR/<scene>.previous-<sha12>/ and a warning says so, before anything new is written.
#include <filesystem>
#include <optional>
#include <string>

namespace granmix::compare {

// The scene SHA-256 in a table's provenance lines ("# scene: …  sha256: <hex>"); empty when the file has none.
std::string provenance_sha256(const std::filesystem::path& table);

// Moves out/<name>/ aside when one of its tables names a scene SHA-256 other than `sha256`; returns the warning
// (naming the folder, the file read and the folder it went to), or nothing when the folder is absent or consistent.
std::optional<std::string> set_aside_other_scene(const std::filesystem::path& out, const std::string& name, const std::string& sha256);

}  // namespace granmix::compare
