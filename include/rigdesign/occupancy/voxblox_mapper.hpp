#pragma once
/// Voxblox's projective TSDF (Oleynikova et al., "Voxblox: Incremental 3D Euclidean Signed
/// Distance Fields for On-Board MAV Planning", IROS 2017, section III-A, and the voxblox_ros
/// documentation, The-Voxblox-Node.rst), reimplemented from those texts for paper 3's
/// comparison (never from Voxblox's code):
/// - every ray runs from the sensor origin (voxel carving on) to truncation distance delta
///   behind its point; a voxel's distance is the projective one, d = |p - o| minus the
///   projection of (voxel centre - o) on the ray, truncated to [-delta, delta];
/// - a point's weight is 1 / z^2 with z its depth in the sensor's frame (the optical axis for a
///   camera, the z axis of the frame a lidar driver publishes in), or 1 with use_const_weight;
///   behind the surface it drops linearly from full at -epsilon (epsilon = one voxel) to 0 at
///   -delta; weights add up to max_weight, distances are weighted means;
/// - the merged integrator (Voxblox's default): the points of a cloud ending in one voxel
///   become one ray to their weighted mean with their summed weight;
/// - points nearer than min_ray_length are dropped; farther than max_ray_length (and points
///   below min_height, the comparison's rule for ground) they only clear: the ray stops delta
///   before them;
/// - the occupied set is one of voxblox_ros's own outputs (VoxbloxOccupiedRule); which one
///   paper 3 read is not in its text (docs/occupancy.md).
/// Only voxels inside the scored window are kept (a dense array): voxels outside never change
/// one inside, since each voxel's update depends on its own ray geometry alone.
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "rigdesign/occupancy/occupancy_voxel_mapper.hpp"

namespace rigdesign::occupancy {

/// Which axis of a sensor's frame is a point's depth for the 1/z^2 weight.
enum class DepthAxis {
  /// A lidar: the z axis of the frame its driver publishes in (REP-103: up), as Voxblox takes
  /// it: points level with the lidar get very large weights (docs/occupancy.md).
  frame_z,
  /// A camera: its optical axis (z of the optical frame, x of REP-103's body frame).
  optical,
};

/// Which of voxblox_ros's outputs is the occupied set (ethz-asl/voxblox c8066b0,
/// voxblox_ros/include/voxblox_ros/ptcloud_vis.h). Neither topic is published by default
/// (tsdf_server.cc: publish_pointclouds false; only the mesh goes out), so paper 3 turned one on.
enum class VoxbloxOccupiedRule {
  /// The `occupied_nodes` markers: weight > 1e-3 and d <= one voxel (ptcloud_vis.h L282-290,
  /// L431-440). Free space is clamped to d = +truncation, so with truncation <= voxel every
  /// voxel a ray has crossed is "occupied".
  occupied_nodes,
  /// The `surface_pointcloud`: weight > 0 and |d| < 0.75 voxel (tsdf_server.cc L429-430,
  /// ptcloud_vis.h L177-189); with truncation < 0.75 voxel the same fill.
  surface_pointcloud,
};

struct VoxbloxParams {
  double voxel = 0.1;       ///< [m] tsdf_voxel_size (paper 3's reference row)
  double truncation = 0.1;  ///< [m] truncation_distance (paper 3's reference row, Tab. 8)
  bool use_const_weight = false;
  double max_weight = 1e4;      ///< documented default
  double min_ray_length = 0.1;  ///< [m] documented default
  double max_ray_length = 5.0;  ///< [m] documented default
  VoxbloxOccupiedRule occupied_rule = VoxbloxOccupiedRule::occupied_nodes;
  double min_height = 0.1;   ///< [m] lower points only clear
  double window_size = 6.0;  ///< [m] square window centred on the world origin
  double z_max = 2.0;        ///< [m] top of the scored band
};

/// The TSDF itself, over the window's dense voxel array.
class VoxbloxTsdf {
 public:
  /// Throws std::invalid_argument for parameters out of range.
  explicit VoxbloxTsdf(const VoxbloxParams& params);
  /// One cloud (world frame, its sensor's origin and orientation set), merged integrator.
  void integrate(const model::PointCloud& cloud, DepthAxis axis);

  struct Voxel {
    float distance = 0.0f;  ///< [m] fused projective distance, in [-truncation, truncation]
    float weight = 0.0f;    ///< 0: never updated
  };
  /// The voxel at a lattice key (x, y on the lattice, z layer from 0 m); a zero voxel outside
  /// the window.
  Voxel at(const costmap::VoxelKey& key) const;
  /// The voxels `occupied_rule` shows, ascending.
  std::vector<costmap::VoxelKey> occupied() const;
  const VoxbloxParams& params() const { return params_; }
  /// [bytes] the dense window's distances and weights (Voxblox allocates 16^3 blocks only
  /// where rays pass, so its own footprint is smaller where much of the window is unseen).
  std::size_t memory_bytes() const { return (distance_.size() + weight_.size()) * sizeof(float); }

 private:
  struct MergedRay {
    model::Vec3 weighted_sum = model::Vec3::Zero();
    double weight = 0.0;
  };
  double point_weight(const model::Vec3& offset, const Eigen::Quaterniond& R_world_sensor,
                      DepthAxis axis) const;
  void cast(const model::Vec3& origin, const MergedRay& ray, bool clearing);

  VoxbloxParams params_;
  costmap::GridWindow window_;
  int layers_ = 1;
  Eigen::Vector3i size_;
  Eigen::Matrix<std::ptrdiff_t, 3, 1> stride_;
  model::Vec3 corner_;
  std::vector<float> distance_;
  std::vector<float> weight_;
  std::unordered_map<std::int64_t, MergedRay> marking_, clearing_;
};

/// "Voxblox 0.1 m, trunc 0.1 m" (", const weight" when set).
std::string voxblox_label(const VoxbloxParams& params);

/// One depth axis per cloud the mapper will be given, in the same order. Throws
/// std::invalid_argument for parameters out of range.
std::unique_ptr<OccupancyMapper> make_voxblox_mapper(const VoxbloxParams& params,
                                                     std::vector<DepthAxis> depth_axes);

}  // namespace rigdesign::occupancy
