// glTF 2.0 of the rig: positions and indices in one buffer, one mesh, material and node per
// part, under a root node that stands the z-up robot frame upright in glTF's y-up world.
#include "rigdesign/render/gltf_scene.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>

#include "rigdesign/geometry/body_mesh.hpp"
#include "rigdesign/geometry/body_occluder.hpp"
#include "rigdesign/geometry/housing_geometry.hpp"
#include "rigdesign/render/fov_mesh.hpp"

namespace rigdesign::render {
namespace {

constexpr int kFloat = 5126;         // glTF componentType FLOAT
constexpr int kUnsignedInt = 5125;   // UNSIGNED_INT
constexpr int kArrayBuffer = 34962;  // bufferView target of vertex attributes
constexpr int kElementArrayBuffer = 34963;
constexpr int kTriangles = 4;  // primitive mode

// RFC 4648 base64, as glTF's data URIs carry buffers.
std::string base64(const std::vector<std::uint8_t>& bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  text.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t a = bytes[i];
    const std::uint32_t b = i + 1 < bytes.size() ? bytes[i + 1] : 0;
    const std::uint32_t c = i + 2 < bytes.size() ? bytes[i + 2] : 0;
    const std::uint32_t triple = (a << 16) | (b << 8) | c;
    text += kAlphabet[(triple >> 18) & 63];
    text += kAlphabet[(triple >> 12) & 63];
    text += i + 1 < bytes.size() ? kAlphabet[(triple >> 6) & 63] : '=';
    text += i + 2 < bytes.size() ? kAlphabet[triple & 63] : '=';
  }
  return text;
}

template <class T>
void append(std::vector<std::uint8_t>& buffer, T value) {
  std::uint8_t raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));  // glTF is little-endian, as this machine
  buffer.insert(buffer.end(), raw, raw + sizeof(T));
}

}  // namespace

std::string gltf_scene(const std::string& scene_name, const std::string& frame, double frame_height,
                       const std::vector<GltfPart>& parts) {
  nlohmann::json gltf;
  gltf["asset"] = {{"version", "2.0"}, {"generator", "rigdesign"}};
  // -90 deg about x: the robot frame's +z (up) becomes glTF's +y (up); then down by the
  // frame's height (glTF applies the rotation first), so the scene's origin is the frame's.
  const double half = std::sqrt(0.5);
  nlohmann::json root = {{"name", frame},
                         {"rotation", {-half, 0.0, 0.0, half}},
                         {"translation", {0.0, -frame_height, 0.0}}};
  nlohmann::json nodes = nlohmann::json::array({root});
  nlohmann::json children = nlohmann::json::array();
  std::vector<std::uint8_t> buffer;
  for (const GltfPart& part : parts) {
    if (part.mesh.triangles.empty()) continue;
    const std::size_t index = gltf["meshes"].size();
    // Positions, with the bounds glTF requires of a POSITION accessor.
    const std::size_t positions_at = buffer.size();
    std::vector<double> low(3, std::numeric_limits<double>::infinity());
    std::vector<double> high(3, -std::numeric_limits<double>::infinity());
    for (const model::Vec3& v : part.mesh.vertices) {
      for (int k = 0; k < 3; ++k) {
        const auto value = static_cast<float>(v[k]);
        append(buffer, value);
        low[static_cast<std::size_t>(k)] =
            std::min(low[static_cast<std::size_t>(k)], double{value});
        high[static_cast<std::size_t>(k)] =
            std::max(high[static_cast<std::size_t>(k)], double{value});
      }
    }
    const std::size_t indices_at = buffer.size();
    for (const auto& triangle : part.mesh.triangles)
      for (const int i : triangle) append(buffer, static_cast<std::uint32_t>(i));
    const std::size_t view = gltf["bufferViews"].size();
    gltf["bufferViews"].push_back({{"buffer", 0},
                                   {"byteOffset", positions_at},
                                   {"byteLength", indices_at - positions_at},
                                   {"target", kArrayBuffer}});
    gltf["bufferViews"].push_back({{"buffer", 0},
                                   {"byteOffset", indices_at},
                                   {"byteLength", buffer.size() - indices_at},
                                   {"target", kElementArrayBuffer}});
    const std::size_t accessor = gltf["accessors"].size();
    gltf["accessors"].push_back({{"bufferView", view},
                                 {"componentType", kFloat},
                                 {"count", part.mesh.vertices.size()},
                                 {"type", "VEC3"},
                                 {"min", low},
                                 {"max", high}});
    gltf["accessors"].push_back({{"bufferView", view + 1},
                                 {"componentType", kUnsignedInt},
                                 {"count", 3 * part.mesh.triangles.size()},
                                 {"type", "SCALAR"}});
    const bool blend = part.opacity < 1.0;
    gltf["materials"].push_back(
        {{"name", part.name},
         {"pbrMetallicRoughness",
          {{"baseColorFactor", {part.colour.r, part.colour.g, part.colour.b, part.opacity}},
           {"metallicFactor", 0.0},
           {"roughnessFactor", 1.0}}},
         {"alphaMode", blend ? "BLEND" : "OPAQUE"},
         // A FOV volume is looked at from inside as often as from outside.
         {"doubleSided", true}});
    gltf["meshes"].push_back({{"name", part.name},
                              {"primitives",
                               {{{"attributes", {{"POSITION", accessor}}},
                                 {"indices", accessor + 1},
                                 {"material", index},
                                 {"mode", kTriangles}}}}});
    children.push_back(nodes.size());
    nodes.push_back({{"name", part.name}, {"mesh", index}});
  }
  if (!children.empty()) nodes[0]["children"] = children;
  gltf["nodes"] = nodes;
  gltf["scenes"] = {{{"name", scene_name}, {"nodes", {0}}}};
  gltf["scene"] = 0;
  if (!buffer.empty()) {
    gltf["buffers"] = {{{"byteLength", buffer.size()},
                        {"uri", "data:application/octet-stream;base64," + base64(buffer)}}};
  }
  return gltf.dump(1) + "\n";
}

std::vector<GltfPart> rig_gltf_parts(const model::Rig& rig, const model::SensorLibrary& library) {
  std::vector<GltfPart> parts;
  parts.push_back({"body", geometry::body_mesh(rig.body), kBodyColour, 1.0});
  for (model::BodyPart& support : geometry::support_parts(rig))
    parts.push_back({support.link, std::move(support.triangles), kBodyColour, 1.0});
  // The coverage engine's occluder, so the volumes agree with the numbers.
  const geometry::BodyOccluder body(rig.body);
  for (std::size_t i = 0; i < rig.mounts.size(); ++i) {
    const model::Mount& mount = rig.mounts[i];
    const model::SensorMode& mode = *library.find(mount.sensor_id)->find_mode(mount.mode_id);
    parts.push_back({mount.id,
                     visible_fov_mesh(mode, mount.T_robot_sensor, rig.distance_of_interest, body),
                     sensor_colour(i), 0.35});
    // Its datasheet housing, opaque in the sensor's colour (issue 52 item 2).
    if (auto housing = geometry::mount_housing(mount, library))
      parts.push_back(
          {mount.id + " housing", std::move(housing->triangles), sensor_colour(i), 1.0});
  }
  return parts;
}

}  // namespace rigdesign::render
