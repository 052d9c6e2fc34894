#include <sstream>

#include "rigdesign/io/deploy/deployment_files.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::io {
namespace {

std::string boolean(bool value) {
  return value ? "true" : "false";
}

void write_comment(std::ostringstream& out, const std::string& text, const std::string& indent) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) out << indent << "# " << line << '\n';
}

std::string footprint_text(const std::vector<model::Vec2>& footprint) {
  std::string text = "\"[";
  for (std::size_t i = 0; i < footprint.size(); ++i) {
    text += (i ? ", [" : "[") + model::exact_number(footprint[i].x()) + ", " +
            model::exact_number(footprint[i].y()) + "]";
  }
  return text + "]\"";
}

std::string obstacle_layer_name(const deploy::CostmapConfig& config) {
  return config.costmap.layer == costmap::ObstacleLayerKind::voxel ? "voxel_layer"
                                                                   : "obstacle_layer";
}

// The keys both costmaps share: footprint, the obstacle or voxel layer with its sources, the
// Hit Layer and the inflation layer.
void write_layers(std::ostringstream& out, const deploy::CostmapConfig& config,
                  const std::string& in) {
  const costmap::CostmapParams& p = config.costmap;
  if (config.footprint.empty()) {
    out << in << "robot_radius: " << model::exact_number(config.robot_radius) << '\n';
  } else {
    out << in << "footprint: " << footprint_text(config.footprint) << '\n';
  }
  const bool voxel = p.layer == costmap::ObstacleLayerKind::voxel;
  out << in << obstacle_layer_name(config) << ":\n";
  const std::string l = in + "  ";
  out << l << "plugin: \"nav2_costmap_2d::" << (voxel ? "VoxelLayer" : "ObstacleLayer") << "\"\n";
  out << l << "enabled: true\n";
  if (voxel) {
    out << l << "publish_voxel_map: true\n";
    out << l << "origin_z: " << model::exact_number(p.voxel.z_min) << '\n';
    out << l << "z_resolution: " << model::exact_number(p.voxel.z_resolution) << '\n';
    out << l << "z_voxels: "
        << static_cast<int>((p.voxel.z_max - p.voxel.z_min) / p.voxel.z_resolution + 0.5) << '\n';
    out << l << "unknown_threshold: " << p.voxel.unknown_threshold << '\n';
    out << l << "mark_threshold: 0\n";
  }
  out << l << "observation_sources:";
  for (const deploy::SourceConfig& source : config.sources) out << ' ' << source.mount_id;
  out << '\n';
  for (const deploy::SourceConfig& source : config.sources) {
    const costmap::ObservationSource& s = source.source;
    out << l << source.mount_id << ":\n";
    const std::string k = l + "  ";
    out << k << "topic: " << source.topic << '\n';
    out << k << "data_type: \"" << (source.laser_scan ? "LaserScan" : "PointCloud2") << "\"\n";
    out << k << "sensor_frame: " << source.sensor_frame << '\n';
    out << k << "marking: " << boolean(s.marking) << '\n';
    out << k << "clearing: " << boolean(s.clearing) << '\n';
    out << k << "obstacle_min_range: " << model::exact_number(s.obstacle_min_range)
        << "  # the sensor's min range\n";
    out << k << "obstacle_max_range: " << model::exact_number(s.obstacle_max_range)
        << "  # reaches the area's far edge (distance of interest)\n";
    out << k << "raytrace_min_range: " << model::exact_number(s.raytrace_min_range)
        << "  # its blind near zone is remembered, not cleared\n";
    out << k << "raytrace_max_range: " << model::exact_number(s.raytrace_max_range) << '\n';
    out << k << "min_obstacle_height: " << model::exact_number(s.min_obstacle_height)
        << "  # floor flatness + 6 sigma of a floor return's height ("
        << model::format_number(source.floor_height_error, 3) << " m)\n";
    out << k << "max_obstacle_height: " << model::exact_number(s.max_obstacle_height)
        << "  # top of the area to perceive\n";
  }
  out << in << "hit_layer:\n";
  write_comment(out, "paper 1's Hit Layer: " + config.memory.rule, l);
  out << l << "plugin: \"rigdesign::HitLayer\"\n";
  out << l << "enabled: true\n";
  out << l << "hit: " << p.hit.hit << '\n';
  out << l << "hit_max: " << p.hit.hit_max << '\n';
  out << l << "d_threshold: " << model::exact_number(p.hit.d_threshold) << '\n';
  out << l << "d_duration: " << model::exact_number(p.hit.d_duration) << '\n';
  out << in << "inflation_layer:\n";
  out << l << "plugin: \"nav2_costmap_2d::InflationLayer\"\n";
  out << l << "enabled: true\n";
  out << l << "inflation_radius: " << model::exact_number(p.inflation.inflation_radius)
      << "  # circumscribed radius + 0.1 m\n";
  out << l << "cost_scaling_factor: " << model::exact_number(p.inflation.cost_scaling_factor)
      << '\n';
}

}  // namespace

std::string nav2_costmap_text(const deploy::CostmapConfig& config, const std::string& header) {
  std::ostringstream out;
  write_comment(out, header, "");
  for (const std::string& note : config.notes) write_comment(out, note, "");
  const costmap::CostmapParams& p = config.costmap;
  const std::string plugins = "\"" + obstacle_layer_name(config) + "\", \"hit_layer\", \"inflation_layer\"";
  out << "local_costmap:\n  local_costmap:\n    ros__parameters:\n";
  const std::string in = "      ";
  out << in << "update_frequency: 5.0\n" << in << "publish_frequency: 2.0\n";
  out << in << "global_frame: odom\n" << in << "robot_base_frame: " << config.robot_base_frame << '\n';
  out << in << "rolling_window: true\n";
  out << in << "width: " << model::exact_number(p.size_x) << "  # twice the distance of interest\n";
  out << in << "height: " << model::exact_number(p.size_y) << '\n';
  out << in << "resolution: " << model::exact_number(p.resolution) << '\n';
  out << in << "plugins: [" << plugins << "]\n";
  write_layers(out, config, in);
  out << "global_costmap:\n  global_costmap:\n    ros__parameters:\n";
  out << in << "update_frequency: 1.0\n" << in << "publish_frequency: 1.0\n";
  out << in << "global_frame: map\n" << in << "robot_base_frame: " << config.robot_base_frame << '\n';
  out << in << "resolution: " << model::exact_number(p.resolution) << '\n';
  out << in << "track_unknown_space: true\n";
  out << in << "plugins: [\"static_layer\", " << plugins << "]\n";
  out << in << "static_layer:\n";
  out << in << "  plugin: \"nav2_costmap_2d::StaticLayer\"\n";
  out << in << "  map_subscribe_transient_local: true\n";
  write_layers(out, config, in);
  return out.str();
}

}  // namespace rigdesign::io
