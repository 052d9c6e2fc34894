#include "rigdesign/io/robot/collision_body.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rigdesign::io {
namespace {

constexpr double kPi = std::numbers::pi;
// A cylinder axis within 1e-6 rad of the robot's z is kept as a vertical cylinder (its top
// then moves by less than 1e-7 m for a 0.1 m radius).
constexpr double kVertical = 1.0 - 1e-12;

model::TriangleMesh box_mesh(const model::Vec3& size) {
  model::TriangleMesh mesh;
  const model::Vec3 h = size / 2;
  for (int i = 0; i < 8; ++i) {
    mesh.vertices.emplace_back(i & 1 ? h.x() : -h.x(), i & 2 ? h.y() : -h.y(),
                               i & 4 ? h.z() : -h.z());
  }
  // Two triangles per face, wound outward.
  mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return mesh;
}

// A prism with a regular polygon of kRoundSides around the z axis, circumscribed so that the
// mesh holds the cylinder (its shadow is never smaller).
model::TriangleMesh cylinder_mesh(double radius, double length) {
  model::TriangleMesh mesh;
  const double outer = radius / std::cos(kPi / kRoundSides);
  for (const double z : {-length / 2, length / 2}) {
    mesh.vertices.emplace_back(0, 0, z);
    for (int k = 0; k < kRoundSides; ++k) {
      const double a = 2 * kPi * k / kRoundSides;
      mesh.vertices.emplace_back(outer * std::cos(a), outer * std::sin(a), z);
    }
  }
  const int top = kRoundSides + 1;
  for (int k = 0; k < kRoundSides; ++k) {
    const int a = 1 + k;
    const int b = 1 + (k + 1) % kRoundSides;
    mesh.triangles.push_back({0, b, a});
    mesh.triangles.push_back({top, top + a, top + b});
    mesh.triangles.push_back({a, b, top + a});
    mesh.triangles.push_back({b, top + b, top + a});
  }
  return mesh;
}

model::TriangleMesh sphere_mesh(double radius) {
  model::TriangleMesh mesh;
  const int bands = kRoundSides / 2;
  // Vertices on a sphere slightly larger than the true one bound it, as for cylinders.
  const double outer = radius / (std::cos(kPi / kRoundSides) * std::cos(kPi / kRoundSides));
  for (int i = 0; i <= bands; ++i) {
    const double polar = kPi * i / bands;
    for (int k = 0; k < kRoundSides; ++k) {
      const double a = 2 * kPi * k / kRoundSides;
      mesh.vertices.emplace_back(outer * std::sin(polar) * std::cos(a),
                                 outer * std::sin(polar) * std::sin(a), outer * std::cos(polar));
    }
  }
  for (int i = 0; i < bands; ++i) {
    for (int k = 0; k < kRoundSides; ++k) {
      const int a = i * kRoundSides + k;
      const int b = i * kRoundSides + (k + 1) % kRoundSides;
      mesh.triangles.push_back({a, a + kRoundSides, b});
      mesh.triangles.push_back({b, a + kRoundSides, b + kRoundSides});
    }
  }
  return mesh;
}

model::BodyPart part_of(const model::CollisionShape& shape, const model::Pose3& T_robot_shape) {
  model::BodyPart part;
  part.link = shape.link;
  part.where = shape.where;
  model::TriangleMesh local;
  switch (shape.kind) {
    case model::CollisionShape::Kind::box: local = box_mesh(shape.size); break;
    case model::CollisionShape::Kind::cylinder: {
      const model::Vec3 axis = T_robot_shape.linear().col(2);
      if (axis.z() * axis.z() >= kVertical) {
        const model::Vec3 centre = T_robot_shape.translation();
        part.cylinder =
            model::VerticalCylinder{centre.head<2>(), shape.radius, centre.z() - shape.length / 2,
                                    centre.z() + shape.length / 2};
        return part;
      }
      local = cylinder_mesh(shape.radius, shape.length);
      part.tessellation_error = shape.radius * (1 / std::cos(kPi / kRoundSides) - 1);
      break;
    }
    case model::CollisionShape::Kind::sphere:
      local = sphere_mesh(shape.radius);
      part.tessellation_error =
          shape.radius * (1 / (std::cos(kPi / kRoundSides) * std::cos(kPi / kRoundSides)) - 1);
      break;
    case model::CollisionShape::Kind::mesh: local = shape.mesh; break;
  }
  part.triangles.append(local, T_robot_shape);
  return part;
}

}  // namespace

model::RobotBody body_from_description(const model::RobotDescription& description,
                                       const std::string& base_link, double base_height) {
  model::RobotBody body;
  model::Pose3 T_robot_root = description.T_root_link.at(base_link).inverse();
  T_robot_root.pretranslate(model::Vec3(0.0, 0.0, base_height));
  for (const model::CollisionShape& shape : description.collisions) {
    model::BodyPart part = part_of(shape, T_robot_root * shape.T_root_shape);
    if (part.cylinder) {
      const model::VerticalCylinder& c = *part.cylinder;
      body.height = std::max(body.height, c.z_max);
      body.radius = std::max(body.radius, c.centre.norm() + c.radius);
    } else if (part.triangles.triangles.empty()) {
      continue;  // a mesh not loaded (poses only)
    }
    for (const model::Vec3& v : part.triangles.vertices) {
      body.height = std::max(body.height, v.z());
      body.radius = std::max(body.radius, v.head<2>().norm());
    }
    body.parts.push_back(std::move(part));
  }
  return body;
}

}  // namespace rigdesign::io
