#include "tsv_writer.hpp"

#include "interrupts.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace granmix::compare {

std::string format_tsv(const std::string& provenance, const model::Table& table) {
  std::string out = provenance;
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    if (c) out += '\t';
    out += table.columns[c];
  }
  out += '\n';
  for (const auto& row : table.rows) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (c) out += '\t';
      // fmt's "{}" is the shortest string that reads back to the same double.
      out += std::isnan(row[c]) ? std::string("nan") : fmt::format("{}", row[c]);
    }
    out += '\n';
  }
  return out;
}

void write_atomically(const std::filesystem::path& path, const std::string& content) {
  interrupts::WriteGuard g;  // an interrupt waits until the file is in place
  std::filesystem::create_directories(path.parent_path());
  // Built step by step: GCC 12 warns falsely (-Wrestrict) on "." + std::string.
  std::string name = ".";
  name += path.filename().string();
  name += ".tmp-";
  name += std::to_string(getpid());
  const std::filesystem::path tmp = path.parent_path() / name;
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (f == nullptr) throw std::runtime_error("cannot write " + tmp.string());
  const bool ok = std::fwrite(content.data(), 1, content.size(), f) == content.size() && std::fflush(f) == 0;
  if (std::fclose(f) != 0 || !ok) {
    std::filesystem::remove(tmp);
    throw std::runtime_error("cannot write " + tmp.string());
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace granmix::compare
