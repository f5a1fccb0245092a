#include "scene_folder.hpp"

#include <fstream>

namespace granmix::compare {

std::string provenance_sha256(const std::filesystem::path& table) {
  std::ifstream in(table);
  std::string line;
  while (std::getline(in, line) && !line.empty() && line.front() == '#') {
    if (line.rfind("# scene: ", 0) != 0) continue;
    const auto at = line.find("  sha256: ");
    if (at != std::string::npos) return line.substr(at + 10);
  }
  return "";
}

std::optional<std::string> set_aside_other_scene(const std::filesystem::path& out, const std::string& name, const std::string& sha256) {
  namespace fs = std::filesystem;
  const fs::path folder = out / name;
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return std::nullopt;
  for (const auto& e : fs::directory_iterator(folder, ec)) {  // every table the commands write carries provenance
    if (e.path().extension() != ".tsv") continue;
    const std::string old = provenance_sha256(e.path());
    if (old.empty() || old == sha256) continue;
    const fs::path aside = out / (name + ".previous-" + old.substr(0, 12));
    fs::remove_all(aside);  // the same old scene set aside before: keep the latest of its outputs
    fs::rename(folder, aside);
    return folder.string() + "/ held outputs of another scene file (" + e.path().filename().string() + ": sha256 " + old.substr(0, 12) +
           "…, this scene: " + sha256.substr(0, 12) + "…); moved to " + aside.string() + "/";
  }
  return std::nullopt;
}

}  // namespace granmix::compare
