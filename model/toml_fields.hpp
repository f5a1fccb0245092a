#pragma once
// Strict reading of one TOML table of a scene: every key is looked up through this class, and
// whatever is left unread at finish() is an unknown key. Every failure is one InputError of the
// form  file:line: table.key: what is wrong (allowed: …)  (docs/architecture.md §4).
#include <toml++/toml.h>

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace granmix::model {

class TomlFields {
 public:
  TomlFields(const toml::table& table, std::string file, std::string path);

  // Also remembers the key as one this table may hold, for "did you mean …?" on an unknown key.
  bool has(const std::string& key) const {
    asked_.insert(key);
    return table_.contains(key);
  }
  // A number (integer or float) in [lo, hi]; required when no default is given.
  double number(const std::string& key, double lo, double hi, std::optional<double> fallback = std::nullopt);
  double positive(const std::string& key, std::optional<double> fallback = std::nullopt);
  // An integer in [lo, hi]; a float is accepted when it is a whole number (particles = 2e4 -> 20000).
  std::size_t count(const std::string& key, std::size_t lo, std::size_t hi, std::optional<std::size_t> fallback);
  bool flag(const std::string& key, bool fallback);
  std::string text(const std::string& key, std::optional<std::string> fallback = std::nullopt);
  std::string choice(const std::string& key, const std::vector<std::string>& allowed,
                     std::optional<std::string> fallback = std::nullopt);
  // One allowed string, or a non-empty array of distinct allowed strings; absent: empty.
  std::vector<std::string> choices(const std::string& key, const std::vector<std::string>& allowed);
  std::vector<double> numbers(const std::string& key, double lo, double hi);  // non-empty array
  // The raw node, marked as read (nullptr when absent).
  const toml::node* node(const std::string& key);
  // A sub-table read with the same rules (path "table.key").
  TomlFields sub(const std::string& key);

  [[noreturn]] void fail(const std::string& key, const std::string& what, const std::string& allowed) const;
  [[noreturn]] void fail_at(const toml::node& at, const std::string& key, const std::string& what,
                            const std::string& allowed) const;
  void finish() const;  // unknown keys -> error naming the keys this table was asked for (and the nearest: "did you mean")

  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }

 private:
  std::string key_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  // " (did you mean …?)" for a key the table lacks when an unknown key of the table is within edit distance 2 of it.
  std::string typo_hint(const std::string& key) const;
  const toml::table& table_;
  std::string file_, path_;
  std::set<std::string> used_;
  mutable std::set<std::string> asked_;  // keys looked for with has(), read or not
};

// Levenshtein distance (insertions, deletions, substitutions), for "did you mean …?".
std::size_t edit_distance(const std::string& a, const std::string& b);

std::string format_number(double v);

}  // namespace granmix::model
