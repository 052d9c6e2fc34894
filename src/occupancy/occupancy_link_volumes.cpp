// Paper 3's link volumes (issue 54 item 2): cylinders and prisms round the actor's links.
#include "rigdesign/occupancy/occupancy_link_volumes.hpp"

#include <algorithm>
#include <cmath>

namespace rigdesign::occupancy {
namespace {

// The prism's width axis: the actor's y made square to the link's axis; for a link along y,
// the actor's x stands in (its depth axis is then the actor's z).
model::Vec3 width_axis(const model::Vec3& along) {
  model::Vec3 across = model::Vec3::UnitY() - along.dot(model::Vec3::UnitY()) * along;
  if (across.norm() < 1e-9) across = model::Vec3::UnitX() - along.dot(model::Vec3::UnitX()) * along;
  return across.normalized();
}

// How far any point of the link's volume lies from `centre`: the segment's farther joint
// (a segment lies within its farther end's distance of any point) plus the volume's reach
// across it.
double reach_from(const sim::BodyLink& link, const model::Vec3& centre) {
  const double across = link.shape == sim::LinkShape::cylinder
                            ? link.radius
                            : 0.5 * std::hypot(link.width, link.depth);
  return std::max((link.start - centre).norm(), (link.end - centre).norm()) + across;
}

}  // namespace

bool in_link_volume(const sim::BodyLink& link, const model::Vec3& p) {
  const model::Vec3 axis = link.end - link.start;
  const double length_squared = axis.squaredNorm();
  if (!(length_squared > 0.0)) return false;
  const model::Vec3 offset = p - link.start;
  const double t = offset.dot(axis) / length_squared;
  if (t < 0.0 || t > 1.0) return false;
  const model::Vec3 radial = offset - t * axis;
  if (link.shape == sim::LinkShape::cylinder) return radial.norm() <= link.radius;
  const model::Vec3 along = axis / std::sqrt(length_squared);
  const model::Vec3 across = width_axis(along);
  const model::Vec3 depth = along.cross(across);
  return std::abs(radial.dot(across)) <= 0.5 * link.width &&
         std::abs(radial.dot(depth)) <= 0.5 * link.depth;
}

std::vector<model::Vec3> points_in_links(std::span<const model::PointCloud> clouds,
                                         const model::Pose3& T_world_actor,
                                         std::span<const sim::BodyLink> links) {
  std::vector<model::Vec3> inside;
  if (links.empty()) return inside;
  // A sphere holding every volume, about the middle of the joints' box (actor frame): the
  // cloud's points outside it are passed over untransformed.
  Eigen::AlignedBox3d joints;
  for (const sim::BodyLink& link : links) joints.extend(link.start), joints.extend(link.end);
  const model::Vec3 middle = joints.center();
  double radius = 0.0;
  for (const sim::BodyLink& link : links) radius = std::max(radius, reach_from(link, middle));
  const model::Pose3 T_actor_world = T_world_actor.inverse();
  const model::Vec3 centre = T_world_actor * middle;
  for (const model::PointCloud& cloud : clouds) {
    for (const model::Point3f& point : cloud.points) {
      const model::Vec3 p = point.cast<double>();
      if ((p - centre).norm() > radius) continue;
      const model::Vec3 p_actor = T_actor_world * p;
      if (std::any_of(links.begin(), links.end(),
                      [&](const sim::BodyLink& link) { return in_link_volume(link, p_actor); }))
        inside.push_back(p);
    }
  }
  return inside;
}

}  // namespace rigdesign::occupancy
