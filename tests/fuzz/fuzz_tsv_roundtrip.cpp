// libFuzzer harness: a table of arbitrary doubles (including ±0, subnormals, ±inf, NaN) written by
// format_tsv (compare/tsv_writer.cpp) reads back bit for bit (NaN as "nan"), and the same values in
// JSON (nlohmann, as report.json and summary.json are written) read back exactly when finite.
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>

#include "compare/tsv_writer.hpp"

namespace {

void require(bool ok) {
  if (!ok) std::abort();  // libFuzzer reports the input
}

bool same(double a, double b) { return (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::size_t ncol = 1 + data[0] % 8;
  granmix::model::Table t;
  for (std::size_t c = 0; c < ncol; ++c) t.columns.push_back("c" + std::to_string(c));
  std::vector<double> values;
  for (std::size_t i = 1; i + sizeof(double) <= size; i += sizeof(double)) {
    double x;
    std::memcpy(&x, data + i, sizeof x);
    if (std::isnan(x)) x = granmix::model::Table::missing;  // the writer knows one NaN: missing
    values.push_back(x);
  }
  for (std::size_t i = 0; i + ncol <= values.size(); i += ncol) t.rows.emplace_back(values.begin() + long(i), values.begin() + long(i + ncol));

  const std::string text = granmix::compare::format_tsv("# provenance\n", t);
  std::istringstream in(text);
  std::string line;
  require(std::getline(in, line) && line == "# provenance");
  require(bool(std::getline(in, line)));
  std::size_t r = 0;
  while (std::getline(in, line)) {
    require(r < t.rows.size());
    std::istringstream cells(line);
    std::size_t c = 0;
    for (std::string cell; std::getline(cells, cell, '\t'); ++c) {
      require(c < ncol);
      char* end = nullptr;
      const double back = std::strtod(cell.c_str(), &end);
      require(end != cell.c_str() && *end == '\0');
      require(same(back, t.rows[r][c]));
    }
    require(c == ncol);
    ++r;
  }
  require(r == t.rows.size());

  nlohmann::json j = values;
  const nlohmann::json back = nlohmann::json::parse(j.dump());
  require(back.size() == values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (std::isfinite(values[i])) require(same(back[i].get<double>(), values[i]));
    else require(back[i].is_null());  // JSON has no inf/NaN: written as null, never as a number
  }
  return 0;
}
