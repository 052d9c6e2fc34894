#pragma once
/// The rig as a glTF 2.0 scene (issue 37): the body and every mount's FOV volume, cut where
/// the body blocks it as the coverage numbers count it, to overlay in Foxglove, RViz (a mesh
/// marker) or Blender. One self-contained .gltf: JSON with the geometry in one base64 buffer.
///
/// glTF is y-up; the meshes stay in the robot frame (REP-103: x forward, y left, z up, metres,
/// origin on the floor) under one root node named after the rig's base link, whose rotation
/// (-90 deg about x) turns z-up into y-up and whose translation lowers the robot frame by the
/// base link's height: the scene's origin is the base link's, so the file overlays on that
/// frame in a viewer, upright, and a reader that wants REP-103 coordinates takes the root's
/// children as they are.
#include <string>
#include <vector>

#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"
#include "rigdesign/model/triangle_mesh.hpp"
#include "rigdesign/render/palette.hpp"

namespace rigdesign::render {

struct GltfPart {
  std::string name;
  model::TriangleMesh mesh;  ///< robot frame
  Rgb colour;
  double opacity = 1.0;  ///< below 1: alpha-blended
};

/// The glTF JSON text. Parts with no triangles are left out. `frame` names the root node,
/// `frame_height` [m] is that frame's height above the robot frame's origin.
std::string gltf_scene(const std::string& scene_name, const std::string& frame, double frame_height,
                       const std::vector<GltfPart>& parts);

/// The body ("body") and each mount's visible FOV volume to the rig's distance of interest
/// (named by the mount's id), coloured as the 3D views colour them. Every mount's sensor and
/// mode must be in `library`.
std::vector<GltfPart> rig_gltf_parts(const model::Rig& rig, const model::SensorLibrary& library);

}  // namespace rigdesign::render
