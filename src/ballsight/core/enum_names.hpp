#pragma once
// An enum's names for messages, options and JSON, from one table of (value, name) pairs.

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <utility>

namespace ballsight {

template <class Enum, std::size_t N>
using EnumNames = std::array<std::pair<Enum, std::string_view>, N>;

/// The name of `value` in `names` ("?" when the table lacks it).
template <class Enum, std::size_t N>
std::string_view enum_name(const EnumNames<Enum, N>& names, Enum value) {
  for (const auto& [v, name] : names) {
    if (v == value) return name;
  }
  return "?";
}

/// The value named `name`, or nullopt.
template <class Enum, std::size_t N>
std::optional<Enum> enum_named(const EnumNames<Enum, N>& names, std::string_view name) {
  for (const auto& [v, n] : names) {
    if (n == name) return v;
  }
  return std::nullopt;
}

}  // namespace ballsight
