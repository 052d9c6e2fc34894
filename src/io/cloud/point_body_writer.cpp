#include "io/cloud/point_body_writer.hpp"

#include <bit>
#include <cstring>

#include "io/cloud/cloud_text.hpp"

namespace rigdesign::io {

// Both formats' binary bodies are little-endian; the floats are copied as they are.
static_assert(std::endian::native == std::endian::little,
              "cloud_io writes binary bodies without byte swapping");
// Eigen stores a Vector3f as three packed floats, so a point vector is already a body.
static_assert(sizeof(model::Point3f) == 3 * sizeof(float));

void append_viewpoint_values(std::string& text, const model::PointCloud& cloud) {
  const Eigen::Quaternionf& q = cloud.orientation;
  for (const float value :
       {cloud.origin.x(), cloud.origin.y(), cloud.origin.z(), q.w(), q.x(), q.y(), q.z()}) {
    text += ' ';
    text += format_float(value);
  }
}

void append_point_body(std::string& text, const model::PointCloud& cloud, CloudEncoding encoding) {
  if (encoding == CloudEncoding::ascii) {
    for (const model::Point3f& p : cloud.points) {
      text += format_float(p.x()) + ' ' + format_float(p.y()) + ' ' + format_float(p.z()) + '\n';
    }
    return;
  }
  if (cloud.empty()) return;
  const std::size_t header_size = text.size();
  text.resize(header_size + cloud.size() * sizeof(model::Point3f));
  std::memcpy(text.data() + header_size, cloud.points.data(),
              cloud.size() * sizeof(model::Point3f));
}

}  // namespace rigdesign::io
