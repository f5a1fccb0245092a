#pragma once
// A fresh, empty folder under the system's temporary directory for one test. Its name carries a key
// of this build (the path of its granmix): two checkouts running their tests at once (CI clones,
// worktrees, the mutation harness) never clear each other's folders.
#include <filesystem>
#include <functional>
#include <string>

namespace granmix::test {

inline std::filesystem::path fresh_dir(const std::string& name) {
  static const std::string key = std::to_string(std::hash<std::string>{}(GRANMIX_EXE) % 1000000007u);
  const auto d = std::filesystem::temp_directory_path() / ("granmix-test-" + key + "-" + name);
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

}  // namespace granmix::test
