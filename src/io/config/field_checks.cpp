#include "io/config/field_checks.hpp"

#include "rigdesign/model/format_number.hpp"

namespace rigdesign::io {

void read_if_present(MapReader& reader, const std::string& key, double& value,
                     const std::string& expected) {
  if (const auto v = reader.number(key, Need::optional, expected)) value = *v;
}

void read_if_present(MapReader& reader, const std::string& key, int& value,
                     const std::string& expected) {
  if (const auto v = reader.integer(key, Need::optional, expected)) value = *v;
}

void read_if_present(MapReader& reader, const std::string& key, bool& value) {
  if (const auto v = reader.boolean(key, Need::optional)) value = *v;
}

double positive(MapReader& reader, const std::string& key, Need need, const std::string& expected) {
  const auto value = reader.number(key, need, expected);
  if (!value) return 0.0;
  reader.require(*value > 0, key, "must be > 0, got " + model::format_number(*value), expected);
  return *value;
}

double non_negative(MapReader& reader, const std::string& key, Need need,
                    const std::string& expected) {
  const auto value = reader.number(key, need, expected);
  if (!value) return 0.0;
  reader.require(*value >= 0, key, "must be >= 0, got " + model::format_number(*value), expected);
  return *value;
}

double angle_in(MapReader& reader, const std::string& key, double low, double high,
                bool high_inclusive, const std::string& expected) {
  const auto value = reader.number(key, Need::required, expected);
  if (!value) return 0.0;
  const bool ok = *value > low && (high_inclusive ? *value <= high : *value < high);
  reader.require(ok, key, "is out of range: " + model::format_number(*value), expected);
  return *value;
}

double elevation(MapReader& reader, const std::string& key, const std::string& expected) {
  const auto value = reader.number(key, Need::required, expected);
  if (!value) return 0.0;
  reader.require(*value >= -90 && *value <= 90, key,
                 "is out of range: " + model::format_number(*value), expected);
  return *value;
}

std::optional<double> share(MapReader& reader, const std::string& key, Need need,
                            const std::string& expected) {
  const auto value = reader.number(key, need, expected);
  if (!value) return std::nullopt;
  const bool ok = *value >= 0 && *value <= 1;
  reader.require(ok, key, "is out of range: " + model::format_number(*value), expected);
  return ok ? value : std::nullopt;
}

model::Basis basis(MapReader& reader, Need need) {
  return named_value(reader, "basis", need, model::kBasisNames).value_or(model::Basis::estimate);
}

}  // namespace rigdesign::io
