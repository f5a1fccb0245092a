#pragma once
// The '#' lines every output file starts with (docs/architecture.md §4): granmix version and git SHA, scene
// name and SHA-256, seed, fidelity, date, command.
#include <string>

namespace granmix::compare {

struct Provenance {
  std::string scene_name, scene_file, scene_sha256;
  std::string seed = "none (theory is deterministic)";
  std::string fidelity = "n/a";
  std::string command;
  std::string level_choice;  // level = "auto": the level chosen and why (a line only when set)
};

std::string provenance_header(const Provenance& p);
std::string utc_now_iso8601();

}  // namespace granmix::compare
