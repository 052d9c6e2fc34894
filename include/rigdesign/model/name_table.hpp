#pragma once
/// A closed set's names as one table beside its enum, so printing, parsing and the "expected
/// one of" messages cannot drift apart. Tables list the values in enum order (checked at
/// compile time with `covers_in_order`), so a value added to the enum without a name fails to
/// build once the table's size assertion names the new last value.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rigdesign::model {

template <typename Enum, std::size_t N>
using NameTable = std::array<std::pair<Enum, std::string_view>, N>;

/// Whether the table holds the values 0, 1, ..., N-1 in that order: every value once.
template <typename Enum, std::size_t N>
constexpr bool covers_in_order(const NameTable<Enum, N>& table) {
  for (std::size_t i = 0; i < N; ++i) {
    if (static_cast<std::size_t>(table[i].first) != i) return false;
  }
  return true;
}

/// The name of `value`.
template <typename Enum, std::size_t N>
constexpr std::string_view name_in(const NameTable<Enum, N>& table, Enum value) {
  for (const auto& [candidate, name] : table) {
    if (candidate == value) return name;
  }
  return "?";
}

/// The value called `name`, if any.
template <typename Enum, std::size_t N>
constexpr std::optional<Enum> value_in(const NameTable<Enum, N>& table, std::string_view name) {
  for (const auto& [value, candidate] : table) {
    if (candidate == name) return value;
  }
  return std::nullopt;
}

/// Every name in table order, for parsers and messages.
template <typename Enum, std::size_t N>
std::vector<std::string> names_of(const NameTable<Enum, N>& table) {
  std::vector<std::string> names;
  for (const auto& entry : table) names.emplace_back(entry.second);
  return names;
}

}  // namespace rigdesign::model
