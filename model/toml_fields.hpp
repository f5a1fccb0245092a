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

  bool has(const std::string& key) const { return table_.contains(key); }
  // A number (integer or float) in [lo, hi]; required when no default is given.
  double number(const std::string& key, double lo, double hi, std::optional<double> fallback = std::nullopt);
  double positive(const std::string& key, std::optional<double> fallback = std::nullopt);
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
  void finish() const;  // unknown keys -> error naming the keys this table was asked for

  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }

 private:
  std::string key_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  const toml::table& table_;
  std::string file_, path_;
  std::set<std::string> used_;
};

std::string format_number(double v);

}  // namespace granmix::model
