// Output files: the SHA-256 of provenance headers and the TSV format of docs/architecture.md §4.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "model/sha256.hpp"
#include "compare/tsv_writer.hpp"
#include "run_cli.hpp"

using namespace granmix;

TEST_CASE("SHA-256 of the FIPS 180-4 test vectors", "[compare]") {
  CHECK(model::sha256_hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  CHECK(model::sha256_hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  CHECK(model::sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
        "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  CHECK(model::sha256_hex(std::string(1000, 'a')).size() == 64);  // multi-block message
}

TEST_CASE("TSV: provenance - one header line - full-precision numbers - nan", "[compare]") {
  model::Table t;
  t.columns = {"t", "species", "msd"};
  t.rows = {{0.1, 1, 1.0 / 3.0}, {1e-300, 0, model::Table::missing}};
  const std::string s = compare::format_tsv("# provenance\n", t);
  std::istringstream in(s);
  std::string line;
  std::getline(in, line);
  CHECK(line == "# provenance");
  std::getline(in, line);
  CHECK(line == "t\tspecies\tmsd");
  double a = 0, b = 0, c = 0;
  in >> a >> b >> c;
  CHECK(c == 1.0 / 3.0);  // shortest round-trip: reads back bit for bit
  std::getline(in, line);
  std::getline(in, line);
  CHECK(line == "1e-300\t0\tnan");
}

TEST_CASE("atomic write leaves only the final file", "[compare]") {
  const auto d = test::fresh_dir("atomic");
  compare::write_atomically(d / "sub" / "x.tsv", "hello\n");
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(d / "sub")) ++files;
  CHECK(files == 1);
  std::ifstream in(d / "sub" / "x.tsv");
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(content == "hello\n");
}
