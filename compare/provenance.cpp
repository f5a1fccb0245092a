#include "provenance.hpp"

#include <ctime>

#include "granmix_version.hpp"

namespace granmix::compare {

std::string utc_now_iso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

std::string provenance_header(const Provenance& p) {
  std::string h;
  h += std::string("# granmix ") + granmix::version + " (git " + granmix::git_sha + ")\n";
  h += "# scene: " + p.scene_name + "  file: " + p.scene_file + "  sha256: " + p.scene_sha256 + "\n";
  h += "# seed: " + p.seed + "\n";
  h += "# fidelity: " + p.fidelity + "\n";
  h += "# date: " + utc_now_iso8601() + "\n";
  h += "# command: " + p.command + "\n";
  if (!p.level_choice.empty()) h += "# level: " + p.level_choice + "\n";
  return h;
}

}  // namespace granmix::compare
