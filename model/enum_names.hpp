#pragma once
// Names of an enum's values, for parsing user input and printing: one table per enum instead of a
// parse switch and a to_string switch each.
#include <array>
#include <stdexcept>
#include <string>
#include <utility>

namespace granmix::model {

template <class E, std::size_t N>
using EnumNames = std::array<std::pair<E, const char*>, N>;

template <class E, std::size_t N>
E parse_enum(const EnumNames<E, N>& names, const std::string& text, const char* what) {
  for (const auto& [value, name] : names)
    if (text == name) return value;
  throw std::invalid_argument(std::string("unknown ") + what + " '" + text + "'");
}

template <class E, std::size_t N>
const char* enum_name(const EnumNames<E, N>& names, E value) {
  for (const auto& [v, name] : names)
    if (v == value) return name;
  return "?";
}

}  // namespace granmix::model
