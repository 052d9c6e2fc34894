#pragma once
/// Ground-truth collision check for a robot body that is a vertical cylinder (DESIGN.md
/// section 7, issue 6 item 2): the scene's triangles are cut to the height band the body
/// occupies and projected onto the floor, and the body's clearance is the distance from its
/// axis to the nearest of those pieces minus its radius.
#include <limits>
#include <string>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/triangle_mesh.hpp"

namespace rigdesign::costmap {

/// A named mesh to check against (a scene object at the time of the check).
struct NamedMesh {
  std::string name;
  const model::TriangleMesh* mesh = nullptr;  ///< not owned; only read while building the checker
};

/// The body's vertical extent [m], world z: from `bottom` (the lowest part above the floor,
/// so the floor itself is not an obstacle) to `top` (RobotBody::height).
struct HeightBand {
  double bottom = 0.02;
  double top = 1.0;
};

struct Clearance {
  /// [m] distance from the body's surface to the nearest obstacle piece: negative when the
  /// body overlaps one (down to -radius with the axis on it); infinity when nothing lies in
  /// the band. Surfaces are checked, so a body wholly inside a closed volume whose walls it
  /// does not touch would read clear; a driving body always enters through a wall first.
  double distance = std::numeric_limits<double>::infinity();
  std::string object;  ///< name of the nearest object (empty when none)
};

class FootprintCollisionChecker {
 public:
  /// Cuts every triangle of `meshes` to `band` and keeps the floor-plane pieces (convex
  /// polygons; a vertical triangle becomes a segment). Triangles outside the band are dropped.
  FootprintCollisionChecker(const std::vector<NamedMesh>& meshes, const HeightBand& band);

  /// Clearance of a vertical cylinder of `radius` [m] whose axis stands at `centre_world` [m].
  /// The body collides when the distance is negative. Exact; O(pieces).
  Clearance clearance(const model::Vec2& centre_world, double radius) const;

  std::size_t pieces() const { return pieces_.size(); }
  /// The floor-plane outlines of every piece, for drawing.
  std::vector<std::vector<model::Vec2>> outlines() const;

 private:
  struct Piece {
    std::vector<model::Vec2> polygon;  ///< convex, in order; 1 to 5 vertices
    Eigen::AlignedBox2d bounds;
    int object = 0;
  };
  std::vector<Piece> pieces_;
  std::vector<std::string> names_;
};

/// Distance [m] from `p` to a convex polygon given by its vertices in order (0 inside it);
/// one vertex is a point, two a segment. Exposed for tests.
double distance_to_convex_polygon(const model::Vec2& p, const std::vector<model::Vec2>& polygon);

}  // namespace rigdesign::costmap
