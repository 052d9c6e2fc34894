#pragma once
/// Where each sensor sees its own robot (issue 14), found by casting the sensor's rays (its
/// ray pattern, sim::ray_pattern) against the body's closed mesh (geometry::body_mesh): a 2D
/// scanner gets the scan angles whose rays hit the body, as bands a laser_filters
/// LaserScanAngularBoundsFilterInPlace chain drops; a 3D sensor gets, per body part it hits,
/// the box around the hit points (padded by the sensor's noise), as pcl_ros CropBox filters.
/// A part that holds the sensor origin is its own housing and is left out, as in coverage.
#include <string>
#include <vector>

#include "rigdesign/model/mount_limits.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::deploy {

struct SelfBox {
  std::string part;                       ///< the link (or "body") the box surrounds
  model::Vec3 min = model::Vec3::Zero();  ///< [m] robot frame
  model::Vec3 max = model::Vec3::Zero();
  int hits = 0;  ///< rays that hit inside it
};

struct SelfFilter {
  std::string mount_id;
  bool scanner = false;                   ///< a 2D scanner (bands), else a 3D sensor (boxes)
  std::vector<model::AzimuthBand> bands;  ///< scan angles to drop [rad], sensor frame
  std::vector<SelfBox> boxes;
  int rays = 0;          ///< rays cast
  int body_hits = 0;     ///< rays that hit the body within the sensor's range
  double padding = 0.0;  ///< [m] added around each box: 3 sigma of the noise at the hits
};

struct SelfFilterSettings {
  int camera_decimation = 4;  ///< every k-th pixel row and column (sim::decimated_mode)
  int lidar_decimation = 1;   ///< every ray of a scanner or lidar
};

/// Whether the filter drops anything (a scanner band or a crop box).
inline bool filters_anything(const SelfFilter& filter) {
  return filter.scanner ? !filter.bands.empty() : !filter.boxes.empty();
}

/// The topic a mount's self-filter chain publishes, from the driver's `raw` topic: what the
/// costmap subscribes to. A crop-box chain's box k of n (from 1) reads the previous output
/// (the raw topic for k = 1) and writes crop_box_topic(raw, k, n), the last one this topic.
std::string self_filtered_topic(const std::string& raw);
std::string crop_box_topic(const std::string& raw, std::size_t k, std::size_t n);

/// One entry per mount, in mount order. Precondition: the mounts' modes are in `library`.
std::vector<SelfFilter> self_filters(const model::Rig& rig, const model::SensorLibrary& library,
                                     const SelfFilterSettings& settings = {});

}  // namespace rigdesign::deploy
