#pragma once
/// Paper 3's ground truth as paper 3 finds it (section III-B, eqs. 1-4 as ../shared/DESIGN.md
/// section 9 states them): the fused clouds' points that fall inside volumes built round the
/// actor's links, a cylinder or a prism per link (sim/person_links.hpp). Unlike the ray re-cast
/// (occupancy_actor_points.hpp), it needs only the actor's pose: noise points a little off the
/// body count, and a point of something else inside a volume (the floor under a foot) counts
/// too, as it would for paper 3.
#include <span>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/point_cloud.hpp"
#include "rigdesign/sim/person_links.hpp"

namespace rigdesign::occupancy {

/// Whether `p` (the actor's frame) lies in the link's volume. Our reading of eqs. 1-4: the
/// point's projection on the axis falls between the joints (t = (p - a).(b - a) / |b - a|^2
/// in [0, 1]) and, for a cylinder, its distance from the axis is at most the radius; for a
/// prism, its offsets along the width axis (the actor's y made square to the link) and the
/// depth axis are at most half the width and half the depth. A link of zero length holds
/// nothing.
bool in_link_volume(const sim::BodyLink& link, const model::Vec3& p);

/// The points of `clouds` (world frame) inside any link's volume with the actor at
/// `T_world_actor`, in cloud and point order.
std::vector<model::Vec3> points_in_links(std::span<const model::PointCloud> clouds,
                                         const model::Pose3& T_world_actor,
                                         std::span<const sim::BodyLink> links);

}  // namespace rigdesign::occupancy
