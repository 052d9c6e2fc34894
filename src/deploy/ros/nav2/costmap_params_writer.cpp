#include "rigdesign/deploy/ros/nav2/costmap_params_writer.hpp"

#include <array>
#include <cmath>
#include <sstream>

#include "deploy/ros/nav2/nav2_keys.hpp"
#include "rigdesign/io/emit/yaml_emit.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::deploy {
namespace {

std::string footprint_text(const std::vector<model::Vec2>& footprint) {
  std::string text = "\"[";
  for (std::size_t i = 0; i < footprint.size(); ++i) {
    text += (i ? ", [" : "[") + model::exact_number(footprint[i].x()) + ", " +
            model::exact_number(footprint[i].y()) + "]";
  }
  return text + "]\"";
}

// nav2 declares width and height as whole metres (int): a window side rounded up to one.
std::string whole_metres(double metres) {
  return std::to_string(static_cast<long long>(std::ceil(metres - 1e-9)));
}

// The sources a layer holds: all of them, or with STVL only the 2D scanners (the 3D sources go
// to stvl_layer).
std::vector<const deploy::SourceConfig*> obstacle_sources(const deploy::CostmapConfig& config,
                                                          const deploy::StvlLayer* stvl) {
  std::vector<const deploy::SourceConfig*> sources;
  for (const deploy::SourceConfig& source : config.sources)
    if (!stvl || source.laser_scan) sources.push_back(&source);
  return sources;
}

bool voxel_layer(const deploy::CostmapConfig& config, const deploy::StvlLayer* stvl) {
  return !stvl && config.costmap.layer == costmap::ObstacleLayerKind::voxel;
}

std::string obstacle_layer_name(const deploy::CostmapConfig& config,
                                const deploy::StvlLayer* stvl) {
  return std::string(voxel_layer(config, stvl) ? nav2::kVoxelLayer : nav2::kObstacleLayer);
}

// The obstacle or voxel layer's column and its observation sources.
void write_obstacle_layer(std::ostringstream& out, const deploy::CostmapConfig& config,
                          const deploy::StvlLayer* stvl, const std::string& in) {
  const costmap::CostmapParams& p = config.costmap;
  const bool voxel = voxel_layer(config, stvl);
  const std::vector<const deploy::SourceConfig*> sources = obstacle_sources(config, stvl);
  out << in << obstacle_layer_name(config, stvl) << ":\n";
  const std::string l = in + "  ";
  io::write_key(
      out, l, "plugin",
      io::yaml_quoted(std::string(voxel ? nav2::kVoxelLayerClass : nav2::kObstacleLayerClass)));
  io::write_key(out, l, "enabled", io::yaml_bool(true));
  if (voxel) {
    io::write_key(out, l, "publish_voxel_map", io::yaml_bool(true));
    io::write_key(out, l, "origin_z", io::yaml_float(p.voxel.z_min - config.global_frame_height),
                  "the floor, in the global frame");
    io::write_key(out, l, "z_resolution", io::yaml_float(p.voxel.z_resolution));
    io::write_key(out, l, "z_voxels",
                  std::to_string(static_cast<int>(
                      (p.voxel.z_max - p.voxel.z_min) / p.voxel.z_resolution + 0.5)));
    io::write_key(out, l, "unknown_threshold", std::to_string(p.voxel.unknown_threshold));
    io::write_key(out, l, "mark_threshold", "0");
  }
  out << l << "observation_sources:";
  for (const deploy::SourceConfig* source : sources)
    out << ' ' << io::yaml_scalar(source->mount_id);
  out << '\n';
  // Why each number is what it is, beside it (deploy/costmap_config.cpp derives them).
  const std::array<std::string, 4> range_why = {
      "the sensor's min range", "reaches the area's far edge (distance of interest)",
      "its blind near zone is remembered, not cleared", ""};
  for (const deploy::SourceConfig* source_of : sources) {
    const deploy::SourceConfig& source = *source_of;
    const costmap::ObservationSource& s = source.source;
    out << l << io::yaml_scalar(source.mount_id) << ":\n";
    const std::string k = l + "  ";
    io::write_key(out, k, "topic", io::yaml_scalar(source.topic));
    io::write_key(out, k, "data_type",
                  io::yaml_quoted(source.laser_scan ? "LaserScan" : "PointCloud2"));
    io::write_key(out, k, "sensor_frame", io::yaml_scalar(source.sensor_frame));
    io::write_key(out, k, "marking", io::yaml_bool(s.marking));
    io::write_key(out, k, "clearing", io::yaml_bool(s.clearing));
    for (std::size_t i = 0; i < nav2::kSourceRangeKeys.size(); ++i) {
      const nav2::SourceNumberKey& range = nav2::kSourceRangeKeys[i];
      io::write_key(out, k, range.key, io::yaml_float(s.*range.field), range_why[i]);
    }
    const std::array<std::string, 2> height_why = {
        "floor flatness + " + model::format_number(config.floor_noise_sigmas) +
            " sigma of a floor return's height (" +
            model::format_number(source.floor_height_error, 3) + " m)",
        "top of the area to perceive"};
    for (std::size_t i = 0; i < nav2::kSourceHeightKeys.size(); ++i) {
      const nav2::SourceNumberKey& height = nav2::kSourceHeightKeys[i];
      // In the costmap's global frame, which stands global_frame_height above the floor.
      io::write_key(out, k, height.key,
                    io::yaml_float(s.*height.field - config.global_frame_height), height_why[i]);
    }
    io::write_key(out, k, nav2::kObservationPersistence, io::yaml_float(s.observation_persistence),
                  s.observation_persistence > 0.0
                      ? "keeps what then enters a blind gap (the blind memory note above)"
                      : "");
  }
}

// spatio_temporal_voxel_layer with the 3D sources: keys as STVL declares them
// (data/ros_parameters/spatio_temporal_voxel_layer.yaml).
void write_stvl_layer(std::ostringstream& out, const deploy::CostmapConfig& config,
                      const deploy::StvlLayer& stvl, const std::string& in) {
  out << in << nav2::kStvlLayer << ":\n";
  const std::string l = in + "  ";
  io::write_key(out, l, "plugin", io::yaml_quoted(std::string(nav2::kStvlLayerClass)));
  io::write_key(out, l, "enabled", io::yaml_bool(true));
  io::write_key(out, l, "voxel_size", io::yaml_float(stvl.voxel_size), "the costmap's resolution");
  io::write_key(out, l, "decay_model", "0", "linear");
  io::write_key(out, l, "voxel_decay", io::yaml_float(stvl.voxel_decay), stvl.decay_rule);
  io::write_key(out, l, "track_unknown_space", io::yaml_bool(true));
  io::write_key(out, l, "mark_threshold", "0");
  io::write_key(out, l, "update_footprint_enabled", io::yaml_bool(true));
  io::write_key(out, l, "combination_method", "1", "max with the layers below");
  io::write_key(out, l, "publish_voxel_map", io::yaml_bool(true));
  io::write_key(out, l, "mapping_mode", io::yaml_bool(false));
  out << l << "observation_sources:";
  for (const deploy::StvlSource& s : stvl.sources)
    out << ' ' << io::yaml_scalar(config.sources[s.source].mount_id);
  out << '\n';
  for (const deploy::StvlSource& s : stvl.sources) {
    const deploy::SourceConfig& source = config.sources[s.source];
    const costmap::ObservationSource& o = source.source;
    out << l << io::yaml_scalar(source.mount_id) << ":\n";
    const std::string k = l + "  ";
    if (!s.note.empty()) out << io::yaml_comment(s.note, k);
    io::write_key(out, k, "topic", io::yaml_scalar(source.topic));
    io::write_key(out, k, "data_type", io::yaml_quoted("PointCloud2"));
    io::write_key(out, k, "sensor_frame", io::yaml_scalar(source.sensor_frame));
    io::write_key(out, k, "marking", io::yaml_bool(o.marking));
    io::write_key(out, k, "clearing", io::yaml_bool(o.clearing && s.vertical_fov > 0.0));
    io::write_key(out, k, "obstacle_range", io::yaml_float(o.obstacle_max_range),
                  "reaches the area's far edge (distance of interest)");
    // STVL filters heights only with the passthrough or voxel filter, in the global frame.
    io::write_key(out, k, "filter", io::yaml_quoted("passthrough"),
                  "applies the height band below");
    io::write_key(out, k, "min_obstacle_height",
                  io::yaml_float(o.min_obstacle_height - config.global_frame_height),
                  "floor flatness + " + model::format_number(config.floor_noise_sigmas) +
                      " sigma of a floor return's height");
    io::write_key(out, k, "max_obstacle_height",
                  io::yaml_float(o.max_obstacle_height - config.global_frame_height),
                  "top of the area to perceive");
    io::write_key(out, k, "observation_persistence", io::yaml_float(0.0),
                  "memory is voxel_decay's");
    io::write_key(out, k, "inf_is_valid", io::yaml_bool(false));
    io::write_key(out, k, "clear_after_reading", io::yaml_bool(true));
    io::write_key(
        out, k, "model_type", std::to_string(static_cast<int>(s.model)),
        s.model == deploy::StvlModel::depth_camera ? "depth camera frustum" : "3D lidar band");
    io::write_key(out, k, "min_z", io::yaml_float(s.min_z),
                  "the sensor's min range: not cleared nearer");
    io::write_key(out, k, "max_z", io::yaml_float(s.max_z), "the raytrace range");
    io::write_key(out, k, "horizontal_fov_angle", io::yaml_float(s.horizontal_fov),
                  s.model == deploy::StvlModel::lidar_3d && s.horizontal_fov > 6.27 ? "a full turn"
                                                                                    : "the mode's");
    io::write_key(out, k, "vertical_fov_angle", io::yaml_float(s.vertical_fov));
    io::write_key(out, k, "vertical_fov_padding", io::yaml_float(0.0));
    io::write_key(out, k, "decay_acceleration", io::yaml_float(0.0));
  }
}

// The keys both costmaps share: footprint, the obstacle or voxel layer with its sources (and
// stvl_layer), the Hit Layer and the inflation layer.
void write_layers(std::ostringstream& out, const deploy::CostmapConfig& config,
                  const deploy::StvlLayer* stvl, const std::string& in) {
  const costmap::CostmapParams& p = config.costmap;
  if (config.footprint.empty()) {
    io::write_key(out, in, "robot_radius", io::yaml_float(config.robot_radius));
  } else {
    io::write_key(out, in, "footprint", footprint_text(config.footprint));
  }
  if (!obstacle_sources(config, stvl).empty()) write_obstacle_layer(out, config, stvl, in);
  if (stvl) write_stvl_layer(out, config, *stvl, in);
  const std::string l = in + "  ";
  if (p.use_hit_layer) {
    out << in << nav2::kHitLayer << ":\n";
    out << io::yaml_comment(
        "paper 1's Hit Layer (not part of nav2: the class given to export "
        "--hit-layer-plugin): " +
            config.memory.rule,
        l);
    io::write_key(out, l, "plugin", io::yaml_quoted(config.hit_layer_class));
    io::write_key(out, l, "enabled", io::yaml_bool(true));
    io::write_key(out, l, "hit", std::to_string(p.hit.hit));
    io::write_key(out, l, "hit_max", std::to_string(p.hit.hit_max));
    io::write_key(out, l, "d_threshold", io::yaml_float(p.hit.d_threshold));
    io::write_key(out, l, "d_duration", io::yaml_float(p.hit.d_duration));
  }
  out << in << nav2::kInflationLayer << ":\n";
  io::write_key(out, l, "plugin", io::yaml_quoted(std::string(nav2::kInflationLayerClass)));
  io::write_key(out, l, "enabled", io::yaml_bool(true));
  io::write_key(out, l, "inflation_radius", io::yaml_float(p.inflation.inflation_radius),
                "circumscribed radius + " + model::format_number(config.inflation_margin) + " m");
  io::write_key(out, l, "cost_scaling_factor", io::yaml_float(p.inflation.cost_scaling_factor));
}

// nav2's nesting of a costmap node's parameters: <name>: <name>: ros__parameters:.
void write_costmap_block(std::ostringstream& out, const std::string& name) {
  out << name << ":\n  " << name << ":\n    ros__parameters:\n";
}

}  // namespace

std::string nav2_costmap_text(const deploy::CostmapConfig& config, const std::string& header,
                              const deploy::StvlLayer* stvl) {
  std::ostringstream out;
  out << io::yaml_comment(header);
  out << io::yaml_comment(
      "Heights (min/max_obstacle_height, origin_z) are in the global frame (odom), "
      "taken to stand " +
      model::format_number(config.global_frame_height) +
      " m above the floor (export --global-frame-height; read back with "
      "costmap/check --global-frame-height " +
      model::format_number(config.global_frame_height) + ").");
  for (const std::string& note : config.notes) out << io::yaml_comment(note);
  const costmap::CostmapParams& p = config.costmap;
  std::string layers;
  if (!obstacle_sources(config, stvl).empty())
    layers = io::yaml_quoted(obstacle_layer_name(config, stvl)) + ", ";
  if (stvl) layers += io::yaml_quoted(std::string(nav2::kStvlLayer)) + ", ";
  const std::string plugins =
      layers +
      (p.use_hit_layer ? io::yaml_quoted(std::string(nav2::kHitLayer)) + ", " : std::string()) +
      io::yaml_quoted(std::string(nav2::kInflationLayer));
  const std::string in = "      ";
  write_costmap_block(out, "local_costmap");
  io::write_key(out, in, "update_frequency", io::yaml_float(config.update_rate));
  io::write_key(out, in, "publish_frequency", io::yaml_float(2.0));
  io::write_key(out, in, "global_frame", "odom");
  io::write_key(out, in, "robot_base_frame", io::yaml_scalar(config.robot_base_frame));
  io::write_key(out, in, "rolling_window", io::yaml_bool(true));
  io::write_key(out, in, "width", whole_metres(p.size_x),
                "twice the distance of interest, in whole metres (nav2 declares an int)");
  io::write_key(out, in, "height", whole_metres(p.size_y));
  io::write_key(out, in, "resolution", io::yaml_float(p.resolution));
  io::write_key(out, in, "plugins", "[" + plugins + "]");
  write_layers(out, config, stvl, in);
  write_costmap_block(out, "global_costmap");
  io::write_key(out, in, "update_frequency", io::yaml_float(1.0));
  io::write_key(out, in, "publish_frequency", io::yaml_float(1.0));
  io::write_key(out, in, "global_frame", "map");
  io::write_key(out, in, "robot_base_frame", io::yaml_scalar(config.robot_base_frame));
  io::write_key(out, in, "resolution", io::yaml_float(p.resolution));
  io::write_key(out, in, "track_unknown_space", io::yaml_bool(true));
  io::write_key(out, in, "plugins",
                "[" + io::yaml_quoted(std::string(nav2::kStaticLayer)) + ", " + plugins + "]");
  out << in << nav2::kStaticLayer << ":\n";
  io::write_key(out, in + "  ", "plugin", io::yaml_quoted(std::string(nav2::kStaticLayerClass)));
  io::write_key(out, in + "  ", "map_subscribe_transient_local", io::yaml_bool(true));
  write_layers(out, config, stvl, in);
  return out.str();
}

}  // namespace rigdesign::deploy
