#pragma once
// TSV files of docs/architecture.md §4: provenance '#' lines, ONE uncommented header line of column names,
// then tab-separated numbers in shortest round-trip form (full double precision; NaN as "nan").
// Files are written to a temporary name in the same folder and renamed: never half-written.
#include <filesystem>
#include <string>

#include "model/table.hpp"

namespace granmix::compare {

std::string format_tsv(const std::string& provenance, const model::Table& table);
void write_atomically(const std::filesystem::path& path, const std::string& content);

}  // namespace granmix::compare
