#pragma once
// Reads the TSV files of docs/architecture.md §4 back for tests: '#' lines, one header line, numbers ("nan" too).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace granmix::test {

// A file without its '#' lines (provenance: date and command differ between runs; the data must not).
inline std::string data_lines(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::string line, out;
  while (std::getline(in, line))
    if (line.rfind("#", 0) != 0) out += line + "\n";
  return out;
}

struct Tsv {
  std::vector<std::string> comments, columns;
  std::vector<std::vector<double>> rows;
  double at(std::size_t row, const std::string& col) const {
    for (std::size_t c = 0; c < columns.size(); ++c)
      if (columns[c] == col) return rows.at(row)[c];
    throw std::runtime_error("no column " + col);
  }
};

inline Tsv read_tsv(const std::filesystem::path& p) {
  std::ifstream in(p);
  Tsv t;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("#", 0) == 0) {
      t.comments.push_back(line);
    } else if (t.columns.empty()) {
      std::istringstream s(line);
      for (std::string c; std::getline(s, c, '\t');) t.columns.push_back(c);
    } else {
      std::istringstream s(line);
      std::vector<double> row;
      for (std::string c; std::getline(s, c, '\t');) row.push_back(std::stod(c));
      t.rows.push_back(row);
    }
  }
  return t;
}

}  // namespace granmix::test
