#include "rigdesign/io/logs/ground_truth_files.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>

#include "io/logs/csv_fields.hpp"
#include "io/text_encoding.hpp"
#include "rigdesign/io/config/yaml_reader.hpp"
#include "rigdesign/model/coordinate_limit.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {
namespace {

constexpr const char* kTruthHeader = "bssid,x,y,z";

}  // namespace

std::vector<localize::EmitterTruth> parse_emitter_truth(const std::string& text,
                                                        const std::string& file) {
  const std::vector<std::string> names = {"bssid", "x", "y", "z"};
  std::vector<localize::EmitterTruth> truth;
  for (const csv::Row& row : csv::named_columns(text, file, names, kTruthHeader)) {
    localize::EmitterTruth item;
    item.bssid = row.fields[0].text;
    for (std::size_t i = 1; i < names.size(); ++i) {
      const csv::Field& f = row.fields[i];
      item.position[static_cast<Eigen::Index>(i - 1)] =
          csv::parse_number(f, {file, row.number, f.column}, names[i]);
    }
    truth.push_back(item);
  }
  return truth;
}

std::vector<localize::EmitterTruth> read_emitter_truth(const std::string& path) {
  return parse_emitter_truth(csv::read_text_file(path), path);
}

std::string to_emitter_truth_csv(const std::vector<localize::EmitterTruth>& truth) {
  std::string text = std::string(kTruthHeader) + "\n";
  for (const localize::EmitterTruth& item : truth) {
    text += item.bssid + "," + model::format_number(item.position.x(), 10) + "," +
            model::format_number(item.position.y(), 10) + "," +
            model::format_number(item.position.z(), 10) + "\n";
  }
  return text;
}

std::vector<localize::Artifact> read_artifacts(const std::string& path) {
  const std::string text = csv::read_text_file(path);
  require_utf8(text, path);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& error) {
    throw model::InputError(model::Diagnostic{
        {path, error.mark.line + 1, error.mark.column + 1}, "document", error.msg, "JSON"});
  }
  const YAML::Node list = root.IsMap() ? root["artifacts"] : YAML::Node();
  if (!list || !list.IsSequence()) {
    throw model::InputError(model::Diagnostic{
        {path, 1, 1}, "artifacts", "is missing or not a list", "{\"artifacts\": [...]}"});
  }
  std::vector<localize::Artifact> artifacts;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const YAML::Node item = list[i];
    const std::string prefix = "artifacts[" + std::to_string(i) + "]";
    if (!item.IsMap()) {
      throw model::InputError(model::Diagnostic{location_of(item, path), prefix, "is not a map",
                                                "{\"id\": 1, \"type\": ..., \"x\": ..., ...}"});
    }
    localize::Artifact artifact;
    const auto scalar = [&](const char* key) {
      const YAML::Node node = item[key];
      if (!node || !node.IsScalar()) {
        throw model::InputError(model::Diagnostic{location_of(item, path), prefix + "." + key,
                                                  "is missing", "a value"});
      }
      return node;
    };
    const auto coordinate = [&](const char* key) {
      const YAML::Node node = scalar(key);
      const double value = node.as<double>();
      if (!std::isfinite(value) || std::abs(value) > model::kMaxCoordinate) {
        throw model::InputError(model::Diagnostic{location_of(node, path), prefix + "." + key,
                                                  "is " + node.Scalar(),
                                                  "a coordinate within +-1e8 m"});
      }
      return value;
    };
    try {
      artifact.id = scalar("id").as<int>();
      artifact.type = scalar("type").as<std::string>();
      artifact.position = {coordinate("x"), coordinate("y"), coordinate("z")};
    } catch (const YAML::BadConversion& error) {
      throw model::InputError(model::Diagnostic{{path, error.mark.line + 1, error.mark.column + 1},
                                                prefix + ".x/y/z/id",
                                                "is not a number",
                                                "numbers for id, x, y, z"});
    }
    artifacts.push_back(artifact);
  }
  return artifacts;
}

}  // namespace rigdesign::io
