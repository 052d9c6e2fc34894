#include "rigdesign/geometry/housing_geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace rigdesign::geometry {
namespace {

// The prism's corners in the sensor frame: bottom ring then top ring, circumscribed about the
// cylinder so that every point of the cylinder is inside.
std::vector<model::Vec3> prism_corners(const model::HousingSolid& housing) {
  const double circumscribed = housing.radius() / std::cos(std::numbers::pi / kHousingPrismSides);
  const double half = 0.5 * housing.size.z();
  std::vector<model::Vec3> corners;
  for (const double z : {-half, half}) {
    for (int k = 0; k < kHousingPrismSides; ++k) {
      const double phi = 2 * std::numbers::pi * k / kHousingPrismSides;
      corners.push_back(housing.center + model::Vec3(circumscribed * std::cos(phi),
                                                     circumscribed * std::sin(phi), z));
    }
  }
  return corners;
}

std::vector<model::Vec3> box_corners(const model::HousingSolid& housing) {
  std::vector<model::Vec3> corners;
  const model::Vec3 half = 0.5 * housing.size;
  for (int i = 0; i < 8; ++i) {
    corners.push_back(housing.center + model::Vec3((i & 1) ? half.x() : -half.x(),
                                                   (i & 2) ? half.y() : -half.y(),
                                                   (i & 4) ? half.z() : -half.z()));
  }
  return corners;
}

std::vector<model::Vec3> sensor_frame_corners(const model::HousingSolid& housing) {
  return housing.shape == model::HousingShape::box ? box_corners(housing) : prism_corners(housing);
}

// The interval `corners` project to on `axis`.
std::array<double, 2> projection(const std::vector<model::Vec3>& corners, const model::Vec3& axis) {
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  for (const model::Vec3& p : corners) {
    const double t = axis.dot(p);
    low = std::min(low, t);
    high = std::max(high, t);
  }
  return {low, high};
}

// How far one interval must move along the axis to leave the other, either way.
double separation_needed(const ConvexSolid& a, const ConvexSolid& b, const model::Vec3& axis) {
  const auto [a_low, a_high] = projection(a.corners, axis);
  const auto [b_low, b_high] = projection(b.corners, axis);
  return std::min(a_high - b_low, b_high - a_low);
}

}  // namespace

ConvexSolid housing_solid(const model::HousingSolid& housing, const model::Pose3& T_robot_sensor,
                          double inset) {
  model::HousingSolid shrunk = housing;
  shrunk.size = (housing.size - model::Vec3::Constant(2 * inset)).cwiseMax(0.0);
  ConvexSolid solid;
  for (const model::Vec3& p : sensor_frame_corners(shrunk)) {
    solid.corners.push_back(T_robot_sensor * p);
  }
  const model::Mat3 R = T_robot_sensor.linear();
  if (housing.shape == model::HousingShape::box) {
    for (int axis = 0; axis < 3; ++axis) {
      solid.face_normals.push_back(R.col(axis));
      solid.edge_directions.push_back(R.col(axis));
    }
    return solid;
  }
  solid.face_normals.push_back(R.col(2));
  solid.edge_directions.push_back(R.col(2));
  // Opposite sides of an even-sided prism are parallel: half of them give every direction.
  for (int k = 0; k < kHousingPrismSides / 2; ++k) {
    const double phi = 2 * std::numbers::pi * (k + 0.5) / kHousingPrismSides;
    solid.face_normals.push_back(R * model::Vec3(std::cos(phi), std::sin(phi), 0.0));
    solid.edge_directions.push_back(R * model::Vec3(-std::sin(phi), std::cos(phi), 0.0));
  }
  return solid;
}

model::TriangleMesh housing_mesh(const model::HousingSolid& housing,
                                 const model::Pose3& T_robot_sensor) {
  model::TriangleMesh mesh;
  for (const model::Vec3& p : sensor_frame_corners(housing)) {
    mesh.vertices.push_back(T_robot_sensor * p);
  }
  if (housing.shape == model::HousingShape::box) {
    // Corner i has bit 0 = +x, bit 1 = +y, bit 2 = +z; each face as two triangles, outward.
    static constexpr std::array<std::array<int, 3>, 12> kBoxFaces = {{{0, 2, 1},
                                                                      {1, 2, 3},
                                                                      {4, 5, 6},
                                                                      {5, 7, 6},
                                                                      {0, 1, 4},
                                                                      {1, 5, 4},
                                                                      {2, 6, 3},
                                                                      {3, 6, 7},
                                                                      {0, 4, 2},
                                                                      {2, 4, 6},
                                                                      {1, 3, 5},
                                                                      {3, 7, 5}}};
    mesh.triangles.assign(kBoxFaces.begin(), kBoxFaces.end());
    return mesh;
  }
  const int n = kHousingPrismSides;
  for (int k = 0; k < n; ++k) {
    const int next = (k + 1) % n;
    mesh.triangles.push_back({k, next, n + next});
    mesh.triangles.push_back({k, n + next, n + k});
    if (k > 0 && next > 0) {  // the caps as fans from corner 0 of each ring
      mesh.triangles.push_back({0, next, k});
      mesh.triangles.push_back({n, n + k, n + next});
    }
  }
  return mesh;
}

ConvexSolid triangle_solid(const model::Vec3& a, const model::Vec3& b, const model::Vec3& c) {
  ConvexSolid solid;
  solid.corners = {a, b, c};
  const model::Vec3 normal = (b - a).cross(c - a);
  if (normal.norm() == 0.0) return solid;  // degenerate: its edges still separate it
  solid.face_normals.push_back(normal.normalized());
  const std::array<model::Vec3, 3> edges = {b - a, c - b, a - c};
  for (const model::Vec3& edge : edges) {
    if (edge.norm() == 0.0) continue;
    solid.edge_directions.push_back(edge.normalized());
    solid.face_normals.push_back(normal.cross(edge).normalized());
  }
  return solid;
}

bool contains(const ConvexSolid& solid, const model::Vec3& point) {
  if (solid.corners.empty()) return false;
  // A convex polytope is the intersection of its face slabs: inside every slab, inside it.
  for (const model::Vec3& normal : solid.face_normals) {
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const model::Vec3& corner : solid.corners) {
      low = std::min(low, normal.dot(corner));
      high = std::max(high, normal.dot(corner));
    }
    const double at = normal.dot(point);
    if (at < low - 1e-9 || at > high + 1e-9) return false;
  }
  return true;
}

double penetration(const ConvexSolid& a, const ConvexSolid& b) {
  double least = std::numeric_limits<double>::infinity();
  const auto try_axis = [&](const model::Vec3& axis) {
    least = std::min(least, separation_needed(a, b, axis));
  };
  for (const model::Vec3& n : a.face_normals) try_axis(n);
  for (const model::Vec3& n : b.face_normals) try_axis(n);
  for (const model::Vec3& u : a.edge_directions) {
    for (const model::Vec3& v : b.edge_directions) {
      const model::Vec3 axis = u.cross(v);
      if (axis.norm() > 1e-9) try_axis(axis.normalized());  // parallel edges add nothing new
    }
  }
  return least;
}

std::string housing_part_name(const std::string& mount_id) {
  return "housing of mount '" + mount_id + "'";
}

std::optional<model::BodyPart> mount_housing(const model::Mount& mount,
                                             const model::SensorLibrary& library) {
  const model::Sensor* sensor = library.find(mount.sensor_id);
  if (sensor == nullptr || !sensor->housing) return std::nullopt;
  model::BodyPart part;
  part.link = housing_part_name(mount.id);
  part.triangles = housing_mesh(*sensor->housing, mount.T_robot_sensor);
  if (sensor->housing->shape == model::HousingShape::cylinder) {
    part.tessellation_error =
        sensor->housing->radius() * (1.0 / std::cos(std::numbers::pi / kHousingPrismSides) - 1.0);
  }
  part.where = mount.where;
  return part;
}

std::string support_part_name(const std::string& support_id) {
  return "support '" + support_id + "'";
}

std::vector<model::BodyPart> support_parts(const model::Rig& rig) {
  std::vector<model::BodyPart> parts;
  for (const model::RigSupport& support : rig.supports) {
    model::BodyPart part;
    part.link = support_part_name(support.id);
    part.triangles = housing_mesh(support.solid, support.T_robot_support);
    part.where = support.where;
    parts.push_back(std::move(part));
  }
  return parts;
}

std::vector<model::BodyPart> housings_around(const model::Rig& rig,
                                             const model::SensorLibrary& library,
                                             const std::string& mount_id) {
  std::vector<model::BodyPart> parts;
  for (const model::Mount& mount : rig.mounts) {
    if (mount.id == mount_id) continue;
    if (auto part = mount_housing(mount, library)) parts.push_back(std::move(*part));
  }
  for (model::BodyPart& support : support_parts(rig)) parts.push_back(std::move(support));
  return parts;
}

}  // namespace rigdesign::geometry
