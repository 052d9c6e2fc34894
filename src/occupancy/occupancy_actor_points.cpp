#include "rigdesign/occupancy/occupancy_actor_points.hpp"

#include <algorithm>
#include <cmath>

namespace rigdesign::occupancy {
namespace {

// [m] two first hits closer than this are the same surface: both trees hold the actor's
// triangles with the same coordinates, so the actor's own hit repeats to rounding.
constexpr double kSameHit = 1e-9;

}  // namespace

std::vector<model::Vec3> actor_points(const model::PointCloud& cloud, const sim::RayCaster& scene,
                                      const sim::RayCaster& actor,
                                      const Eigen::AlignedBox3d& actor_box, double reach) {
  std::vector<model::Vec3> points;
  if (actor_box.isEmpty()) return points;
  Eigen::AlignedBox3d near = actor_box;
  near.min().array() -= reach;
  near.max().array() += reach;
  const model::Vec3 origin = cloud.origin.cast<double>();
  for (const model::Point3f& p : cloud.points) {
    const model::Vec3 point = p.cast<double>();
    if (!near.contains(point)) continue;
    const model::Vec3 offset = point - origin;
    const double length = offset.norm();
    if (!(length > 0.0)) continue;
    const model::Vec3 direction = offset / length;
    const std::optional<double> actor_hit = actor.first_hit(origin, direction);
    if (!actor_hit) continue;
    const std::optional<double> scene_hit = scene.first_hit(origin, direction);
    if (scene_hit && std::abs(*scene_hit - *actor_hit) <= kSameHit) points.push_back(point);
  }
  return points;
}

std::vector<costmap::VoxelKey> voxelise_points(std::span<const model::Vec3> points,
                                               const VoxelLattice& lattice, double z_low) {
  std::vector<costmap::VoxelKey> keys;
  keys.reserve(points.size());
  for (const model::Vec3& p : points) {
    if (p.z() < z_low || p.z() >= lattice.z_max) continue;
    keys.push_back(lattice.key_at(p));
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

}  // namespace rigdesign::occupancy
