#pragma once
/// Off-screen 3D technical view of a rig: the robot body, translucent FOV volumes, a floor
/// grid and the robot frame's axes, drawn with an orthographic projection (OSMesa, so no
/// display is needed).
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "rigdesign/render/fov_mesh.hpp"
#include "rigdesign/render/palette.hpp"

namespace rigdesign::render {

enum class Viewpoint {
  isometric,  ///< from the robot's front-left, 35.26 deg above the floor; z up on the image
  top,        ///< straight down: +x (forward) up on the image, +y (left) to the left
};

/// A mesh in the robot frame with how to draw it.
struct ColouredMesh {
  model::TriangleMesh mesh;
  Rgb colour;
  double opacity = 1.0;  ///< [0, 1]; below 1 the mesh is drawn translucent, after opaque ones
};

struct View3dSettings {
  int width = 1200;  ///< [px]
  int height = 900;  ///< [px]
  Viewpoint viewpoint = Viewpoint::isometric;
  /// [m] half-width of the floor square around the robot to frame and draw the grid on (the
  /// frame also holds the meshes' full height); 0 picks the smallest whole number of metres
  /// that holds the meshes.
  double extent = 0.0;
};

/// Renders the meshes (robot frame, REP-103) on white with a light grey 1 m floor grid at
/// z = 0 and 0.5 m x (red), y (green), z (blue) axis arrows at the origin, drawn over
/// everything so the frame stays readable. Opaque meshes are drawn first, then translucent
/// triangles back to front. Anti-aliased by rendering at twice the size and averaging 2 x 2
/// blocks. Returns width * height RGBA pixels (8 bits each, opaque), top row first.
/// Throws std::invalid_argument for a non-positive size, std::runtime_error when no OSMesa
/// context can be created. Deterministic for a given Mesa build.
std::vector<std::uint8_t> render_view_3d_pixels(const std::vector<ColouredMesh>& meshes,
                                                const View3dSettings& settings);

/// Where render_view_3d_pixels puts a point of the robot frame on the image, for labels and
/// scale bars drawn over it.
struct ViewProjection {
  model::Mat3 R_eye_robot = model::Mat3::Identity();
  model::Vec3 centre_eye = model::Vec3::Zero();
  double half_width = 1.0;   ///< [m]
  double half_height = 1.0;  ///< [m]
  int width = 1;             ///< [px]
  int height = 1;            ///< [px]
  /// Pixel (x right, y down, origin top left) of `p_robot`.
  std::pair<double, double> pixel(const model::Vec3& p_robot) const;
  /// Orthographic: a length parallel to the image plane, e.g. along the image's x axis, which
  /// is horizontal in both viewpoints [px/m].
  double pixels_per_metre() const { return width / (2.0 * half_width); }
  double grid_spacing = 1.0;  ///< [m] the floor grid's cell
};
ViewProjection view_projection(const std::vector<ColouredMesh>& meshes,
                               const View3dSettings& settings);

}  // namespace rigdesign::render
