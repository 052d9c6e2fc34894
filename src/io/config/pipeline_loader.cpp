#include "rigdesign/io/config/pipeline_loader.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <type_traits>
#include <variant>

#include "rigdesign/io/config/field_checks.hpp"
#include "rigdesign/io/config/yaml_reader.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::io {
namespace {

using io::MapReader;
using io::Need;

void read_positive(MapReader& m, const std::string& key, double& value,
                   const std::string& expected) {
  if (m.has(key)) value = io::positive(m, key, Need::required, expected);
}

model::RansacPlaneParams read_ransac(MapReader& m, model::RansacPlaneParams params) {
  if (const auto iterations = m.integer("iterations", Need::optional, "an iteration count, > 0")) {
    m.require(*iterations > 0, "iterations", "must be > 0", "an iteration count, > 0");
    params.iterations = *iterations;
  }
  read_positive(m, "threshold", params.threshold, "the inlier distance T in metres, > 0");
  if (const auto confidence = m.number("confidence", Need::optional, "a probability in (0, 1]")) {
    m.require(*confidence > 0 && *confidence <= 1, "confidence", "is out of range",
              "a probability in (0, 1]");
    params.confidence = *confidence;
  }
  if (const auto seed = m.integer("seed", Need::optional, "a non-negative integer")) {
    m.require(*seed >= 0, "seed", "must be >= 0", "a non-negative integer");
    params.seed = static_cast<std::uint64_t>(*seed);
  }
  if (const auto tilt = m.number("max_tilt_deg", Need::optional, "degrees in (0, 90]")) {
    m.require(*tilt > 0 && *tilt <= 90, "max_tilt_deg", "is out of range", "degrees in (0, 90]");
    params.max_tilt = model::deg_to_rad(*tilt);
  }
  m.reject_unknown_keys();
  return params;
}

model::PassThroughParams read_pass_through(MapReader& m) {
  model::PassThroughParams params;
  if (const auto axis = m.choice("axis", Need::optional, {"x", "y", "z"}))
    params.axis = static_cast<int>(*axis);
  read_if_present(m, "min", params.min, "metres");
  read_if_present(m, "max", params.max, "metres");
  m.require(params.min <= params.max, "min", "is above max", "min <= max");
  if (const auto negative = m.boolean("negative", Need::optional)) params.negative = *negative;
  m.reject_unknown_keys();
  return params;
}

// The stage registry's readers, one per alternative of model::StageParams: each fills its
// stage's parameters from the stage's map and rejects other keys.
void read_stage_fields(MapReader& m, model::VoxelGridParams& params) {
  read_positive(m, "leaf", params.leaf, "the voxel size in metres, > 0");
  if (const auto offset = m.numbers("grid_offset", Need::optional, 3, 3, "[x, y, z] in metres")) {
    params.grid_offset = Eigen::Vector3d((*offset)[0], (*offset)[1], (*offset)[2]);
  }
  m.reject_unknown_keys();
}

void read_stage_fields(MapReader& m, model::StatisticalOutlierParams& params) {
  if (const auto k = m.integer("neighbours", Need::optional, "a neighbour count N, > 0")) {
    m.require(*k > 0, "neighbours", "must be > 0", "a neighbour count N, > 0");
    params.neighbours = *k;
  }
  read_if_present(m, "std_multiplier", params.std_multiplier, "M, a number of standard deviations");
  read_positive(m, "cell", params.cell, "the neighbour grid cell in metres, > 0");
  const std::string threads_form =
      "a thread count, 1 to " + std::to_string(model::kMaxFilterThreads);
  if (const auto threads = m.integer("threads", Need::optional, threads_form)) {
    m.require(*threads >= 1 && *threads <= model::kMaxFilterThreads, "threads",
              "is " + std::to_string(*threads), threads_form);
    params.threads = *threads;
  }
  m.reject_unknown_keys();
}

void read_stage_fields(MapReader& m, model::PassThroughParams& params) {
  params = read_pass_through(m);
}

void read_stage_fields(MapReader& m, model::RemovePlaneParams& params) {
  params.ransac = read_ransac(m, params.ransac);
}

void read_stage_fields(MapReader& m, model::FloorRemoval1Params& params) {
  if (auto slice = m.map("slice", Need::optional)) params.slice = read_pass_through(*slice);
  if (auto ransac = m.map("ransac", Need::optional))
    params.ransac = read_ransac(*ransac, params.ransac);
  m.reject_unknown_keys();
}

void read_stage_fields(MapReader& m, model::FloorRemoval2Params& params) {
  if (auto slice = m.map("slice", Need::optional)) params.slice = read_pass_through(*slice);
  read_positive(m, "coarse_leaf", params.coarse_leaf, "V2 in metres, > 0");
  if (auto ransac = m.map("ransac", Need::optional))
    params.ransac = read_ransac(*ransac, params.ransac);
  m.reject_unknown_keys();
}

void read_stage_fields(MapReader& m, model::NegativeObstacleParams& params) {
  read_if_present(m, "below", params.below, "metres (negative: below the floor)");
  read_if_present(m, "virtual_height", params.virtual_height, "metres");
  m.reject_unknown_keys();
}

void read_stage_fields(MapReader& m, model::ThrottleParams& params) {
  read_positive(m, "rate_hz", params.rate_hz, "the frames kept per second, > 0");
  m.reject_unknown_keys();
}

void read_stage_fields(MapReader& m, model::RadiusOutlierParams& params) {
  read_positive(m, "radius", params.radius, "the search radius in metres, > 0");
  if (const auto k = m.integer("min_neighbours", Need::optional, "a neighbour count, > 0")) {
    m.require(*k > 0, "min_neighbours", "must be > 0", "a neighbour count, > 0");
    params.min_neighbours = *k;
  }
  m.reject_unknown_keys();
}

// The stage registered as `name`, its parameters read from `m`; nothing for another name. A
// stage without a read_stage_fields overload fails to compile here.
template <typename... Stages>
std::optional<model::StageParams> read_named_stage(const std::string& name, MapReader& m,
                                                   std::type_identity<std::variant<Stages...>>) {
  std::optional<model::StageParams> stage;
  const auto read_if_named = [&]<typename Stage>(std::type_identity<Stage>) {
    if (stage || name != Stage::kName) return;
    Stage params;
    read_stage_fields(m, params);
    stage = params;
  };
  (read_if_named(std::type_identity<Stages>{}), ...);
  return stage;
}

}  // namespace

model::Pipeline load_pipeline(const std::string& path) {
  model::Diagnostics diagnostics;
  MapReader top = read_document_map(path, diagnostics, "a pipeline: name and stages");
  model::Pipeline pipeline;
  pipeline.name = top.text("name", Need::required, "the pipeline's name").value_or("");
  const YAML::Node stages = top.node("stages");
  if (!stages.IsSequence() || stages.size() == 0) {
    top.require(false, "stages", "is not a non-empty list",
                "a list of stages such as `- voxel_grid: {leaf: 0.03}`");
  } else {
    for (std::size_t i = 0; i < stages.size(); ++i) {
      const std::string field = "stages[" + std::to_string(i) + "]";
      const YAML::Node stage = stages[i];
      const std::string name = stage.IsMap() && stage.size() == 1 ? stage.begin()->first.Scalar()
                               : stage.IsScalar()                 ? stage.Scalar()
                                                                  : "";
      if (std::find(model::kStageNames.begin(), model::kStageNames.end(), name) ==
          model::kStageNames.end()) {
        diagnostics.error(io::location_of(stage, path), field,
                          name.empty() ? "is not a stage" : "unknown stage '" + name + "'",
                          "a map with one stage name: " + model::join(model::stage_names()));
        continue;
      }
      YAML::Node params = stage.IsMap() ? stage.begin()->second : YAML::Node(YAML::NodeType::Map);
      if (params.IsNull()) params = YAML::Node(YAML::NodeType::Map);
      MapReader reader(params, field + "." + name, path, diagnostics, io::location_of(stage, path));
      if (!reader.valid()) {
        diagnostics.error(io::location_of(stage, path), field + "." + name,
                          "is not a map of parameters",
                          "a map such as {leaf: 0.03}, or nothing for the defaults");
        continue;
      }
      pipeline.stages.push_back(
          *read_named_stage(name, reader, std::type_identity<model::StageParams>{}));
    }
  }
  top.text("note", Need::optional);
  top.reject_unknown_keys();
  diagnostics.throw_if_errors();
  return pipeline;
}

}  // namespace rigdesign::io
