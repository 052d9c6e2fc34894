#pragma once
// Range-checked reads shared by the loaders: each reads one field and records a finding
// when it is outside its allowed range. They return a harmless value (0) when the field is
// absent or invalid so that loading carries on and reports every problem at once.
#include <optional>
#include <string>

#include "io/config/yaml_reader.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::io {

/// A number > 0.
/// Sets `value` from `key` when the file has it; leaves the caller's default otherwise.
void read_if_present(MapReader& reader, const std::string& key, double& value,
                     const std::string& expected);
void read_if_present(MapReader& reader, const std::string& key, int& value,
                     const std::string& expected);
void read_if_present(MapReader& reader, const std::string& key, bool& value);

double positive(MapReader& reader, const std::string& key, Need need, const std::string& expected);
/// A number >= 0.
double non_negative(MapReader& reader, const std::string& key, Need need,
                    const std::string& expected);
/// A number in [low, high] (or (low, high] / (low, high) as `high_inclusive` says; low excluded).
double angle_in(MapReader& reader, const std::string& key, double low, double high,
                bool high_inclusive, const std::string& expected);
/// An elevation angle in degrees in [-90, 90].
double elevation(MapReader& reader, const std::string& key, const std::string& expected);
/// A share in [0, 1].
std::optional<double> share(MapReader& reader, const std::string& key, Need need,
                            const std::string& expected);
/// `basis: datasheet | measured | estimate`.
model::Basis basis(MapReader& reader, Need need);

/// A scalar that must be one of `table`'s names; its value.
template <typename Enum, std::size_t N>
std::optional<Enum> named_value(MapReader& reader, const std::string& key, Need need,
                                const model::NameTable<Enum, N>& table) {
  const auto index = reader.choice(key, need, model::names_of(table));
  return index ? std::optional<Enum>(table[*index].first) : std::nullopt;
}

}  // namespace rigdesign::io
