#include "toml_fields.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "errors.hpp"

namespace granmix::model {

std::string format_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

namespace {
std::string type_name(const toml::node& n) {
  if (n.is_string()) return "a string";
  if (n.is_boolean()) return "a boolean";
  if (n.is_array()) return "an array";
  if (n.is_table()) return "a table";
  return "a date or time";
}
}  // namespace

TomlFields::TomlFields(const toml::table& table, std::string file, std::string path)
    : table_(table), file_(std::move(file)), path_(std::move(path)) {}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string TomlFields::typo_hint(const std::string& key) const {
  if (table_.contains(key)) return "";
  std::string best;
  std::size_t dist = 3;  // a typo: at most two edits away
  for (const auto& [k, v] : table_) {
    const std::string name(k.str());
    if (used_.count(name) || asked_.count(name)) continue;  // a key the table knows is not a typo
    const std::size_t d = edit_distance(name, key);
    if (d < dist) dist = d, best = name;
  }
  return best.empty() ? "" : "; found unknown key \"" + best + "\": did you mean \"" + key + "\"?";
}

void TomlFields::fail_at(const toml::node& at, const std::string& key, const std::string& what,
                         const std::string& allowed) const {
  const auto line = at.source().begin.line;
  std::string msg = file_ + ":" + std::to_string(line) + ": " + key_path(key) + ": " + what;
  if (!allowed.empty()) msg += " (allowed: " + allowed + ")";
  throw InputError(msg);
}

void TomlFields::fail(const std::string& key, const std::string& what, const std::string& allowed) const {
  const toml::node* n = table_.get(key);
  fail_at(n ? *n : static_cast<const toml::node&>(table_), key, what + typo_hint(key), allowed);
}

const toml::node* TomlFields::node(const std::string& key) {
  used_.insert(key);
  return table_.get(key);
}

double TomlFields::number(const std::string& key, double lo, double hi, std::optional<double> fallback) {
  const std::string range = "a number in [" + format_number(lo) + ", " + format_number(hi) + "]";
  const toml::node* n = node(key);
  if (n == nullptr) {
    if (fallback) return *fallback;
    fail(key, "missing", range);
  }
  if (!n->is_number()) fail(key, "expected a number, found " + type_name(*n), range);
  const double v = n->value<double>().value();
  if (!std::isfinite(v) || v < lo || v > hi) fail(key, "value " + format_number(v) + " out of range", range);
  return v;
}

double TomlFields::positive(const std::string& key, std::optional<double> fallback) {
  const double v = number(key, 0.0, 1e300, fallback);
  if (!(v > 0.0)) fail(key, "value " + format_number(v) + " must be positive", "a number > 0");
  return v;
}

std::size_t TomlFields::count(const std::string& key, std::size_t lo, std::size_t hi, std::optional<std::size_t> fallback) {
  const std::string range = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  const toml::node* n = node(key);
  if (n == nullptr) {
    if (fallback) return *fallback;
    fail(key, "missing", range);
  }
  if (n->is_floating_point()) {  // 2e4 is a count; 2.5 is not
    const double d = n->value<double>().value();
    if (!std::isfinite(d) || d != std::floor(d))
      fail(key, "expected an integer, found " + format_number(d) + " (not a whole number)", range);
    if (d < static_cast<double>(lo) || d > static_cast<double>(hi)) fail(key, "value " + format_number(d) + " out of range", range);
    return static_cast<std::size_t>(d);
  }
  if (!n->is_integer()) fail(key, "expected an integer, found " + type_name(*n), range);
  const auto v = n->value<std::int64_t>().value();
  if (v < static_cast<std::int64_t>(lo) || v > static_cast<std::int64_t>(hi))
    fail(key, "value " + std::to_string(v) + " out of range", range);
  return static_cast<std::size_t>(v);
}

bool TomlFields::flag(const std::string& key, bool fallback) {
  const toml::node* n = node(key);
  if (n == nullptr) return fallback;
  if (!n->is_boolean()) fail(key, "expected true or false", "true, false");
  return n->value<bool>().value();
}

std::string TomlFields::text(const std::string& key, std::optional<std::string> fallback) {
  const toml::node* n = node(key);
  if (n == nullptr) {
    if (fallback) return *fallback;
    fail(key, "missing", "a string");
  }
  if (!n->is_string()) fail(key, "expected a string", "a string");
  return n->value<std::string>().value();
}

std::string TomlFields::choice(const std::string& key, const std::vector<std::string>& allowed,
                               std::optional<std::string> fallback) {
  std::string list;
  for (const auto& a : allowed) list += (list.empty() ? "\"" : ", \"") + a + "\"";
  const toml::node* n = node(key);
  if (n == nullptr) {
    if (fallback) return *fallback;
    fail(key, "missing", list);
  }
  if (!n->is_string()) fail(key, "expected a string", list);
  const std::string v = n->value<std::string>().value();
  for (const auto& a : allowed)
    if (a == v) return v;
  fail(key, "unknown value \"" + v + "\"", list);
}

std::vector<std::string> TomlFields::choices(const std::string& key, const std::vector<std::string>& allowed) {
  if (!has(key)) return {};
  if (!table_.get(key)->is_array()) return {choice(key, allowed)};
  std::string list;
  for (const auto& a : allowed) list += (list.empty() ? "\"" : ", \"") + a + "\"";
  list = "one of " + list + ", or a non-empty array of distinct ones";
  const toml::array& arr = *node(key)->as_array();
  if (arr.empty()) fail(key, "empty array", list);
  std::vector<std::string> out;
  for (const toml::node& e : arr) {
    if (!e.is_string()) fail_at(e, key, "expected strings", list);
    const std::string v = e.value<std::string>().value();
    if (std::find(allowed.begin(), allowed.end(), v) == allowed.end()) fail_at(e, key, "unknown value \"" + v + "\"", list);
    if (std::find(out.begin(), out.end(), v) != out.end()) fail_at(e, key, "\"" + v + "\" given twice", list);
    out.push_back(v);
  }
  return out;
}

std::vector<double> TomlFields::numbers(const std::string& key, double lo, double hi) {
  const std::string range = "a non-empty array of numbers in [" + format_number(lo) + ", " + format_number(hi) + "]";
  const toml::node* n = node(key);
  if (n == nullptr) fail(key, "missing", range);
  const toml::array* a = n->as_array();
  if (a == nullptr || a->empty()) fail(key, "expected a non-empty array", range);
  std::vector<double> out;
  for (const toml::node& e : *a) {
    if (!e.is_number()) fail_at(e, key, "array element is not a number", range);
    const double v = e.value<double>().value();
    if (!std::isfinite(v) || v < lo || v > hi) fail_at(e, key, "element " + format_number(v) + " out of range", range);
    out.push_back(v);
  }
  return out;
}

TomlFields TomlFields::sub(const std::string& key) {
  const toml::node* n = node(key);
  if (n == nullptr || !n->is_table()) fail(key, n ? "expected a table" : "missing", "a table { … }");
  return TomlFields(*n->as_table(), file_, key_path(key));
}

void TomlFields::finish() const {
  std::set<std::string> known = used_;
  known.insert(asked_.begin(), asked_.end());
  std::string allowed;
  for (const auto& a : known) allowed += (allowed.empty() ? "" : ", ") + a;
  for (const auto& [k, v] : table_) {
    const std::string name(k.str());
    if (used_.count(name)) continue;
    std::string near;
    std::size_t dist = 3;  // a typo: at most two edits away
    for (const auto& a : known)
      if (const std::size_t d = edit_distance(name, a); a != name && d < dist) dist = d, near = a;
    fail_at(v, name, near.empty() ? "unknown key" : "unknown key; did you mean \"" + near + "\"?", allowed);
  }
}

}  // namespace granmix::model
