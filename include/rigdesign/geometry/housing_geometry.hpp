#pragma once
/// A rig's sensor housings (model::HousingSolid) placed on the robot (issue 52 item 2): as
/// triangles that shadow every other sensor, and as convex solids tested for overlap with each
/// other and with the body. A cylinder becomes the 32-sided prism circumscribed about it, so its
/// shadow holds the true one (at most 0.5 % of the radius larger); a box is exact.
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/model/housing_solid.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"
#include "rigdesign/model/triangle_mesh.hpp"

namespace rigdesign::geometry {

/// A convex polytope given by its corners, the normals of its faces and the directions of its
/// edges: enough to decide overlap by separating axes.
struct ConvexSolid {
  std::vector<model::Vec3> corners;
  std::vector<model::Vec3> face_normals;
  std::vector<model::Vec3> edge_directions;
};

/// Sides of the prism that stands for a cylinder housing.
inline constexpr int kHousingPrismSides = 32;

/// The housing moved by `T_robot_sensor` into the robot frame, shrunk by `inset` [m] on every
/// side (a box's lengths and a cylinder's height by 2 inset, its radius by inset; none below 0).
ConvexSolid housing_solid(const model::HousingSolid& housing, const model::Pose3& T_robot_sensor,
                          double inset = 0.0);
/// Its closed surface, outward-facing triangles.
model::TriangleMesh housing_mesh(const model::HousingSolid& housing,
                                 const model::Pose3& T_robot_sensor);
/// A triangle as a flat solid.
ConvexSolid triangle_solid(const model::Vec3& a, const model::Vec3& b, const model::Vec3& c);

/// How deep two convex solids interpenetrate [m]: the least overlap of their projections over
/// every separating-axis candidate (face normals of both, crossings of their edges), which for
/// convex polytopes is the shortest translation that parts them. <= 0: apart or touching.
double penetration(const ConvexSolid& a, const ConvexSolid& b);

/// Whether `point` lies in the solid (its boundary included, to 1e-9 m).
bool contains(const ConvexSolid& solid, const model::Vec3& point);

/// A mount's housing in the robot frame, if its sensor has one: `link` is
/// housing_part_name(mount id), `where` the mount's line.
std::optional<model::BodyPart> mount_housing(const model::Mount& mount,
                                             const model::SensorLibrary& library);
/// The rig's supports (masts, brackets, plates) as parts: `link` is support_part_name(id).
std::vector<model::BodyPart> support_parts(const model::Rig& rig);
/// "support 'front_bracket'": the name a support part carries in place of a link's.
std::string support_part_name(const std::string& support_id);
/// The housings of every mount but `mount_id`, then the rig's supports: what is solid for that
/// mount's sensor besides the body.
std::vector<model::BodyPart> housings_around(const model::Rig& rig,
                                             const model::SensorLibrary& library,
                                             const std::string& mount_id);
/// "housing of mount 'front'": the name a housing part carries in place of a link's.
std::string housing_part_name(const std::string& mount_id);

}  // namespace rigdesign::geometry
