#include "rigdesign/geometry/housing_clearance.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

#include "rigdesign/geometry/bisection.hpp"
#include "rigdesign/geometry/body_mesh.hpp"
#include "rigdesign/geometry/body_occluder.hpp"
#include "rigdesign/geometry/housing_geometry.hpp"
#include "rigdesign/geometry/winding_number.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::geometry {
namespace {

struct Box3 {
  model::Vec3 low;
  model::Vec3 high;
};

Box3 bounds(const std::vector<model::Vec3>& points) {
  Box3 box{points.front(), points.front()};
  for (const model::Vec3& p : points) {
    box.low = box.low.cwiseMin(p);
    box.high = box.high.cwiseMax(p);
  }
  return box;
}

bool apart(const Box3& a, const Box3& b) {
  return (a.high.array() < b.low.array()).any() || (b.high.array() < a.low.array()).any();
}

// Whether `solid` overlaps any triangle of `mesh` (touching is not overlapping).
bool crosses(const ConvexSolid& solid, const model::TriangleMesh& mesh) {
  const Box3 reach = bounds(solid.corners);
  for (const auto& t : mesh.triangles) {
    const model::Vec3& a = mesh.vertices[t[0]];
    const model::Vec3& b = mesh.vertices[t[1]];
    const model::Vec3& c = mesh.vertices[t[2]];
    if (apart(reach, {a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c)})) continue;
    if (penetration(solid, triangle_solid(a, b, c)) > 0.0) return true;
  }
  return false;
}

// A description's vertical cylinder as a convex solid.
ConvexSolid cylinder_solid(const model::VerticalCylinder& c) {
  model::HousingSolid solid;
  solid.shape = model::HousingShape::cylinder;
  solid.size = model::Vec3(2 * c.radius, 2 * c.radius, c.z_max - c.z_min);
  solid.center = model::Vec3(c.centre.x(), c.centre.y(), 0.5 * (c.z_min + c.z_max));
  return housing_solid(solid, model::Pose3::Identity());
}

// Whether a (shrunk) housing meets one solid of the body.
using Meets = std::function<bool(const ConvexSolid& housing)>;

// Bisections of the cut depth: 2^-16 of half the housing's thinnest side, below a micrometre.
constexpr int kDepthSteps = 16;

// How deep the housing cuts into a solid [m]: the largest inset at which the housing, shrunk by
// it on every side, still meets the solid (one standing 12 mm into a wall meets it until shrunk
// by 12 mm). 0 when it does not meet it shrunk by kHousingTouch: touching is allowed.
double cut_depth(const model::HousingSolid& housing, const model::Pose3& T_robot_sensor,
                 const Meets& meets) {
  if (!meets(housing_solid(housing, T_robot_sensor, kHousingTouch))) return 0.0;
  // Shrunk by more than the depth, it no longer meets the solid.
  return bisect(kHousingTouch, 0.5 * housing.size.minCoeff(), kDepthSteps,
                [&](double inset) { return !meets(housing_solid(housing, T_robot_sensor, inset)); })
      .first;
}

// One solid of the body a housing may meet: its link (empty: a cylinder or prism body), its
// line, and the test.
struct BodySolid {
  std::string link;
  model::SourceLocation where;
  Meets meets;
};

// The body's solids but the sensor's own housing link, for a housing centred at `centre`. A
// housing inside a solid, touching none of its faces, meets it too: its centre is inside.
std::vector<BodySolid> body_solids(const model::DescribedRobot& robot,
                                   const std::string& housing_link, const model::Vec3& centre) {
  std::vector<BodySolid> solids;
  if (!robot.body.has_parts()) {
    auto mesh = std::make_shared<const model::TriangleMesh>(body_mesh(robot.body));
    const bool inside = BodyOccluder(robot.body).contains(centre);
    solids.push_back({"", robot.body.where, [mesh, inside](const ConvexSolid& solid) {
                        return inside || crosses(solid, *mesh);
                      }});
    return solids;
  }
  for (const model::BodyPart& part : robot.body.parts) {
    if (!housing_link.empty() && part.link == housing_link) continue;
    if (part.cylinder) {
      const ConvexSolid cylinder = cylinder_solid(*part.cylinder);
      solids.push_back({part.link, part.where, [cylinder](const ConvexSolid& solid) {
                          return penetration(solid, cylinder) > 0.0;
                        }});
      continue;
    }
    const bool inside = inside_part(part, centre);
    const model::TriangleMesh* mesh = &part.triangles;
    solids.push_back({part.link, part.where, [mesh, inside](const ConvexSolid& solid) {
                        return inside || crosses(solid, *mesh);
                      }});
  }
  return solids;
}

// [m] the farthest a housing is searched for something holding it.
constexpr double kLargestGap = 0.5;

// A convex solid beside mount `index`'s housing: another mount's housing or a support.
struct Neighbour {
  std::string mount_id;    // the other mount's id, or empty for a support
  std::string support_id;  // the support's id, or empty for a housing
  model::SourceLocation where;
  ConvexSolid solid;
};

// The other mounts' housings, then the rig's supports.
std::vector<Neighbour> neighbours(const model::Rig& rig, const model::SensorLibrary& library,
                                  std::size_t index) {
  std::vector<Neighbour> found;
  for (std::size_t other = 0; other < rig.mounts.size(); ++other) {
    const model::Mount& mount = rig.mounts[other];
    const model::Sensor* sensor = library.find(mount.sensor_id);
    if (other == index || sensor == nullptr || !sensor->housing) continue;
    found.push_back(
        {mount.id, "", mount.pose_where, housing_solid(*sensor->housing, mount.T_robot_sensor)});
  }
  for (const model::RigSupport& support : rig.supports)
    found.push_back(
        {"", support.id, support.where, housing_solid(support.solid, support.T_robot_support)});
  return found;
}

}  // namespace

std::vector<HousingClash> body_clashes(const model::DescribedRobot& robot,
                                       const std::string& housing_link,
                                       const model::HousingSolid& housing,
                                       const model::Pose3& T_robot_sensor) {
  std::vector<HousingClash> clashes;
  for (const BodySolid& solid : body_solids(robot, housing_link, T_robot_sensor * housing.center)) {
    const double depth = cut_depth(housing, T_robot_sensor, solid.meets);
    if (depth > 0.0) clashes.push_back({solid.link, "", "", solid.where, depth});
  }
  return clashes;
}

std::optional<double> housing_gap(const model::Rig& rig, const model::SensorLibrary& library,
                                  std::size_t index) {
  const model::Mount& mount = rig.mounts.at(index);
  const model::Sensor* sensor = library.find(mount.sensor_id);
  // A sensor on a description link of its own is held by the description, one in a pocket of
  // the shell by the pocket.
  if (sensor == nullptr || !sensor->housing || !mount.housing_link.empty() || mount.recessed)
    return std::nullopt;
  const model::HousingSolid& housing = *sensor->housing;
  std::vector<BodySolid> holders =
      body_solids(rig, mount.housing_link, mount.T_robot_sensor * housing.center);
  for (Neighbour& neighbour : neighbours(rig, library, index)) {
    holders.push_back(
        {"", neighbour.where, [held_by = std::move(neighbour.solid)](const ConvexSolid& solid) {
           return penetration(solid, held_by) > 0.0;
         }});
  }
  // Grown by `gap` on every side (a negative inset), does the housing meet a holder?
  const auto held = [&](double gap) {
    const ConvexSolid grown = housing_solid(housing, mount.T_robot_sensor, -gap);
    return std::any_of(holders.begin(), holders.end(),
                       [&](const BodySolid& holder) { return holder.meets(grown); });
  };
  if (held(kHousingShim)) return std::nullopt;
  if (!held(kLargestGap)) return kLargestGap;
  return bisect(kHousingShim, kLargestGap, kDepthSteps, held).second;
}

bool solids_clash(const ConvexSolid& a, const ConvexSolid& b) {
  return penetration(a, b) > kHousingTouch;
}

std::string HousingClash::what() const {
  const std::string at = where.file.empty() ? "" : " (" + model::to_string(where) + ")";
  if (!mount_id.empty()) return "the housing of mount '" + mount_id + "'" + at;
  if (!support_id.empty()) return "support '" + support_id + "'" + at;
  if (link.empty()) return "the robot body" + at;
  return "the collision geometry of link '" + link + "'" + at;
}

std::string HousingClash::describe() const {
  // Millimetres to a tenth: what a technician measures.
  return "cuts " + model::format_number(std::round(10000 * depth) / 10) + " mm into " + what();
}

std::vector<HousingClash> housing_clashes(const model::Rig& rig,
                                          const model::SensorLibrary& library, std::size_t index) {
  std::vector<HousingClash> clashes;
  const model::Mount& mount = rig.mounts.at(index);
  const model::Sensor* sensor = library.find(mount.sensor_id);
  if (sensor == nullptr || !sensor->housing) return clashes;
  // A sensor in a pocket of the shell may sit inside the body; never inside another housing.
  if (!mount.recessed)
    clashes = body_clashes(rig, mount.housing_link, *sensor->housing, mount.T_robot_sensor);
  const ConvexSolid housing = housing_solid(*sensor->housing, mount.T_robot_sensor);
  for (const Neighbour& neighbour : neighbours(rig, library, index)) {
    if (solids_clash(housing, neighbour.solid)) {
      clashes.push_back({"", neighbour.mount_id, neighbour.support_id, neighbour.where,
                         penetration(housing, neighbour.solid)});
    }
  }
  return clashes;
}

}  // namespace rigdesign::geometry
