#include "rigdesign/io/nav2/costmap_params_writer.hpp"

#include <array>
#include <cmath>
#include <sstream>

#include "io/emit/yaml_emit.hpp"
#include "io/nav2/nav2_keys.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::io {
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
  write_key(out, l, "plugin",
            yaml_quoted(std::string(voxel ? nav2::kVoxelLayerClass : nav2::kObstacleLayerClass)));
  write_key(out, l, "enabled", yaml_bool(true));
  if (voxel) {
    write_key(out, l, "publish_voxel_map", yaml_bool(true));
    write_key(out, l, "origin_z", yaml_float(p.voxel.z_min - config.global_frame_height),
              "the floor, in the global frame");
    write_key(out, l, "z_resolution", yaml_float(p.voxel.z_resolution));
    write_key(out, l, "z_voxels",
              std::to_string(
                  static_cast<int>((p.voxel.z_max - p.voxel.z_min) / p.voxel.z_resolution + 0.5)));
    write_key(out, l, "unknown_threshold", std::to_string(p.voxel.unknown_threshold));
    write_key(out, l, "mark_threshold", "0");
  }
  out << l << "observation_sources:";
  for (const deploy::SourceConfig* source : sources) out << ' ' << yaml_scalar(source->mount_id);
  out << '\n';
  // Why each number is what it is, beside it (deploy/costmap_config.cpp derives them).
  const std::array<std::string, 4> range_why = {
      "the sensor's min range", "reaches the area's far edge (distance of interest)",
      "its blind near zone is remembered, not cleared", ""};
  for (const deploy::SourceConfig* source_of : sources) {
    const deploy::SourceConfig& source = *source_of;
    const costmap::ObservationSource& s = source.source;
    out << l << yaml_scalar(source.mount_id) << ":\n";
    const std::string k = l + "  ";
    write_key(out, k, "topic", yaml_scalar(source.topic));
    write_key(out, k, "data_type", yaml_quoted(source.laser_scan ? "LaserScan" : "PointCloud2"));
    write_key(out, k, "sensor_frame", yaml_scalar(source.sensor_frame));
    write_key(out, k, "marking", yaml_bool(s.marking));
    write_key(out, k, "clearing", yaml_bool(s.clearing));
    for (std::size_t i = 0; i < nav2::kSourceRangeKeys.size(); ++i) {
      const nav2::SourceNumberKey& range = nav2::kSourceRangeKeys[i];
      write_key(out, k, range.key, yaml_float(s.*range.field), range_why[i]);
    }
    const std::array<std::string, 2> height_why = {
        "floor flatness + " + model::format_number(config.floor_noise_sigmas) +
            " sigma of a floor return's height (" +
            model::format_number(source.floor_height_error, 3) + " m)",
        "top of the area to perceive"};
    for (std::size_t i = 0; i < nav2::kSourceHeightKeys.size(); ++i) {
      const nav2::SourceNumberKey& height = nav2::kSourceHeightKeys[i];
      // In the costmap's global frame, which stands global_frame_height above the floor.
      write_key(out, k, height.key, yaml_float(s.*height.field - config.global_frame_height),
                height_why[i]);
    }
    write_key(out, k, nav2::kObservationPersistence, yaml_float(s.observation_persistence),
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
  write_key(out, l, "plugin", yaml_quoted(std::string(nav2::kStvlLayerClass)));
  write_key(out, l, "enabled", yaml_bool(true));
  write_key(out, l, "voxel_size", yaml_float(stvl.voxel_size), "the costmap's resolution");
  write_key(out, l, "decay_model", "0", "linear");
  write_key(out, l, "voxel_decay", yaml_float(stvl.voxel_decay), stvl.decay_rule);
  write_key(out, l, "track_unknown_space", yaml_bool(true));
  write_key(out, l, "mark_threshold", "0");
  write_key(out, l, "update_footprint_enabled", yaml_bool(true));
  write_key(out, l, "combination_method", "1", "max with the layers below");
  write_key(out, l, "publish_voxel_map", yaml_bool(true));
  write_key(out, l, "mapping_mode", yaml_bool(false));
  out << l << "observation_sources:";
  for (const deploy::StvlSource& s : stvl.sources)
    out << ' ' << yaml_scalar(config.sources[s.source].mount_id);
  out << '\n';
  for (const deploy::StvlSource& s : stvl.sources) {
    const deploy::SourceConfig& source = config.sources[s.source];
    const costmap::ObservationSource& o = source.source;
    out << l << yaml_scalar(source.mount_id) << ":\n";
    const std::string k = l + "  ";
    if (!s.note.empty()) out << yaml_comment(s.note, k);
    write_key(out, k, "topic", yaml_scalar(source.topic));
    write_key(out, k, "data_type", yaml_quoted("PointCloud2"));
    write_key(out, k, "sensor_frame", yaml_scalar(source.sensor_frame));
    write_key(out, k, "marking", yaml_bool(o.marking));
    write_key(out, k, "clearing", yaml_bool(o.clearing && s.vertical_fov > 0.0));
    write_key(out, k, "obstacle_range", yaml_float(o.obstacle_max_range),
              "reaches the area's far edge (distance of interest)");
    // STVL filters heights only with the passthrough or voxel filter, in the global frame.
    write_key(out, k, "filter", yaml_quoted("passthrough"), "applies the height band below");
    write_key(out, k, "min_obstacle_height",
              yaml_float(o.min_obstacle_height - config.global_frame_height),
              "floor flatness + " + model::format_number(config.floor_noise_sigmas) +
                  " sigma of a floor return's height");
    write_key(out, k, "max_obstacle_height",
              yaml_float(o.max_obstacle_height - config.global_frame_height),
              "top of the area to perceive");
    write_key(out, k, "observation_persistence", yaml_float(0.0), "memory is voxel_decay's");
    write_key(out, k, "inf_is_valid", yaml_bool(false));
    write_key(out, k, "clear_after_reading", yaml_bool(true));
    write_key(
        out, k, "model_type", std::to_string(static_cast<int>(s.model)),
        s.model == deploy::StvlModel::depth_camera ? "depth camera frustum" : "3D lidar band");
    write_key(out, k, "min_z", yaml_float(s.min_z), "the sensor's min range: not cleared nearer");
    write_key(out, k, "max_z", yaml_float(s.max_z), "the raytrace range");
    write_key(out, k, "horizontal_fov_angle", yaml_float(s.horizontal_fov),
              s.model == deploy::StvlModel::lidar_3d && s.horizontal_fov > 6.27 ? "a full turn"
                                                                                : "the mode's");
    write_key(out, k, "vertical_fov_angle", yaml_float(s.vertical_fov));
    write_key(out, k, "vertical_fov_padding", yaml_float(0.0));
    write_key(out, k, "decay_acceleration", yaml_float(0.0));
  }
}

// The keys both costmaps share: footprint, the obstacle or voxel layer with its sources (and
// stvl_layer), the Hit Layer and the inflation layer.
void write_layers(std::ostringstream& out, const deploy::CostmapConfig& config,
                  const deploy::StvlLayer* stvl, const std::string& in) {
  const costmap::CostmapParams& p = config.costmap;
  if (config.footprint.empty()) {
    write_key(out, in, "robot_radius", yaml_float(config.robot_radius));
  } else {
    write_key(out, in, "footprint", footprint_text(config.footprint));
  }
  if (!obstacle_sources(config, stvl).empty()) write_obstacle_layer(out, config, stvl, in);
  if (stvl) write_stvl_layer(out, config, *stvl, in);
  const std::string l = in + "  ";
  if (p.use_hit_layer) {
    out << in << nav2::kHitLayer << ":\n";
    out << yaml_comment(
        "paper 1's Hit Layer (not part of nav2: the class given to export "
        "--hit-layer-plugin): " +
            config.memory.rule,
        l);
    write_key(out, l, "plugin", yaml_quoted(config.hit_layer_class));
    write_key(out, l, "enabled", yaml_bool(true));
    write_key(out, l, "hit", std::to_string(p.hit.hit));
    write_key(out, l, "hit_max", std::to_string(p.hit.hit_max));
    write_key(out, l, "d_threshold", yaml_float(p.hit.d_threshold));
    write_key(out, l, "d_duration", yaml_float(p.hit.d_duration));
  }
  out << in << nav2::kInflationLayer << ":\n";
  write_key(out, l, "plugin", yaml_quoted(std::string(nav2::kInflationLayerClass)));
  write_key(out, l, "enabled", yaml_bool(true));
  write_key(out, l, "inflation_radius", yaml_float(p.inflation.inflation_radius),
            "circumscribed radius + " + model::format_number(config.inflation_margin) + " m");
  write_key(out, l, "cost_scaling_factor", yaml_float(p.inflation.cost_scaling_factor));
}

// nav2's nesting of a costmap node's parameters: <name>: <name>: ros__parameters:.
void write_costmap_block(std::ostringstream& out, const std::string& name) {
  out << name << ":\n  " << name << ":\n    ros__parameters:\n";
}

}  // namespace

std::string nav2_costmap_text(const deploy::CostmapConfig& config, const std::string& header,
                              const deploy::StvlLayer* stvl) {
  std::ostringstream out;
  out << yaml_comment(header);
  out << yaml_comment(
      "Heights (min/max_obstacle_height, origin_z) are in the global frame (odom), "
      "taken to stand " +
      model::format_number(config.global_frame_height) +
      " m above the floor (export --global-frame-height; read back with "
      "costmap/check --global-frame-height " +
      model::format_number(config.global_frame_height) + ").");
  for (const std::string& note : config.notes) out << yaml_comment(note);
  const costmap::CostmapParams& p = config.costmap;
  std::string layers;
  if (!obstacle_sources(config, stvl).empty())
    layers = yaml_quoted(obstacle_layer_name(config, stvl)) + ", ";
  if (stvl) layers += yaml_quoted(std::string(nav2::kStvlLayer)) + ", ";
  const std::string plugins =
      layers +
      (p.use_hit_layer ? yaml_quoted(std::string(nav2::kHitLayer)) + ", " : std::string()) +
      yaml_quoted(std::string(nav2::kInflationLayer));
  const std::string in = "      ";
  write_costmap_block(out, "local_costmap");
  write_key(out, in, "update_frequency", yaml_float(config.update_rate));
  write_key(out, in, "publish_frequency", yaml_float(2.0));
  write_key(out, in, "global_frame", "odom");
  write_key(out, in, "robot_base_frame", yaml_scalar(config.robot_base_frame));
  write_key(out, in, "rolling_window", yaml_bool(true));
  write_key(out, in, "width", whole_metres(p.size_x),
            "twice the distance of interest, in whole metres (nav2 declares an int)");
  write_key(out, in, "height", whole_metres(p.size_y));
  write_key(out, in, "resolution", yaml_float(p.resolution));
  write_key(out, in, "plugins", "[" + plugins + "]");
  write_layers(out, config, stvl, in);
  write_costmap_block(out, "global_costmap");
  write_key(out, in, "update_frequency", yaml_float(1.0));
  write_key(out, in, "publish_frequency", yaml_float(1.0));
  write_key(out, in, "global_frame", "map");
  write_key(out, in, "robot_base_frame", yaml_scalar(config.robot_base_frame));
  write_key(out, in, "resolution", yaml_float(p.resolution));
  write_key(out, in, "track_unknown_space", yaml_bool(true));
  write_key(out, in, "plugins",
            "[" + yaml_quoted(std::string(nav2::kStaticLayer)) + ", " + plugins + "]");
  out << in << nav2::kStaticLayer << ":\n";
  write_key(out, in + "  ", "plugin", yaml_quoted(std::string(nav2::kStaticLayerClass)));
  write_key(out, in + "  ", "map_subscribe_transient_local", yaml_bool(true));
  write_layers(out, config, stvl, in);
  return out.str();
}

}  // namespace rigdesign::io
