#pragma once
/// Paper 3's ground truth (section III-B, as ../shared/DESIGN.md section 9 states it): the
/// actor's points in the sensors' own clouds, voxelised on the framework's lattice. Paper 3
/// finds them as the points inside volumes built round the actor's links; in simulation the
/// actor is known exactly, so a point is the actor's when the first surface its ray meets is
/// the actor's (a noise-free re-cast of the point's ray against the scene and the actor alone).
/// A face no sensor sees gives no point and so no truth voxel.
#include <span>
#include <vector>

#include "rigdesign/costmap/rolling_voxel_grid.hpp"
#include "rigdesign/model/point_cloud.hpp"
#include "rigdesign/occupancy/occupancy_ground_truth.hpp"
#include "rigdesign/sim/ray_caster.hpp"

namespace rigdesign::occupancy {

/// The points of `cloud` (world frame, origin = the sensor's) whose ray first meets the actor:
/// `scene` holds every triangle at the frame's time, `actor` the actor's alone. Only points
/// within `reach` [m] of `actor_box` are re-cast (range noise moves a point along its ray, so
/// reach = a few sigma of the noisiest sensor). Input order kept.
std::vector<model::Vec3> actor_points(const model::PointCloud& cloud, const sim::RayCaster& scene,
                                      const sim::RayCaster& actor,
                                      const Eigen::AlignedBox3d& actor_box, double reach);

/// The lattice voxels holding the points at heights in [z_low, lattice.z_max), ascending and
/// unique.
std::vector<costmap::VoxelKey> voxelise_points(std::span<const model::Vec3> points,
                                               const VoxelLattice& lattice, double z_low);

}  // namespace rigdesign::occupancy
