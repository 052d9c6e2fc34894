#pragma once
/// A robot as its URDF describes it, with every joint at its zero position: where each link
/// sits and the collision geometry each link carries. Read by io from URDF or xacro; the
/// rig takes its mount poses and its body from it.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/model/description_sensor.hpp"
#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/source_location.hpp"
#include "rigdesign/model/triangle_mesh.hpp"

namespace rigdesign::model {

/// One <collision> element of a link.
struct CollisionShape {
  enum class Kind { box, cylinder, sphere, mesh };
  Kind kind = Kind::box;
  std::string link;
  Pose3 T_root_shape = Pose3::Identity();  ///< the shape's frame in the root link's frame
  Vec3 size = Vec3::Zero();                ///< box edge lengths [m], centred on the frame
  double radius = 0.0;                     ///< cylinder (axis = the frame's z) or sphere [m]
  double length = 0.0;                     ///< cylinder length along z, centred [m]
  std::string mesh_file;                   ///< resolved path of a mesh
  TriangleMesh mesh;                       ///< its triangles in the shape frame, scaled [m]
  SourceLocation where;                    ///< the <collision> element
};

struct RobotDescription {
  std::string name;
  std::string file;
  std::string root_link;
  std::map<std::string, Pose3> T_root_link;  ///< every link's pose in the root link's frame
  std::map<std::string, SourceLocation> link_where;
  /// Every joint's element, and each link's parent link (the root has none): the names an
  /// exported sensor macro must not repeat, and where to find a link's children.
  std::map<std::string, SourceLocation> joint_where;
  std::map<std::string, std::string> parent_link;
  std::vector<CollisionShape> collisions;
  /// The sensors its `<gazebo>` elements declare for the simulator.
  std::vector<DescriptionSensor> sensors;
  /// What the loader noticed that is not an error (an `env` variable nothing reads).
  std::vector<Diagnostic> warnings;

  /// T_base_link: `link`'s pose in `base`'s frame; nothing when either is not a link.
  std::optional<Pose3> T_base(const std::string& base, const std::string& link) const {
    const auto b = T_root_link.find(base);
    const auto l = T_root_link.find(link);
    if (b == T_root_link.end() || l == T_root_link.end()) return std::nullopt;
    return b->second.inverse() * l->second;
  }
};

}  // namespace rigdesign::model
