#include "rigdesign/deploy/ros/description/sensors_xacro_writer.hpp"

#include <cmath>
#include <ostream>
#include <sstream>

#include "rigdesign/io/emit/xml_emit.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/optical_frame.hpp"
#include "rigdesign/model/rotation.hpp"

namespace rigdesign::deploy {
namespace {

// Exact, except that rounding residue below 1e-15 (and -0) is written as 0 for the reader.
std::string xacro_number(double value) {
  return model::exact_number(std::abs(value) < 1e-15 ? 0.0 : value);
}

std::string triple(const model::Vec3& v) {
  return xacro_number(v.x()) + " " + xacro_number(v.y()) + " " + xacro_number(v.z());
}

// `<visual>` and `<collision>` of a housing: a box, or a cylinder along the link's z axis.
void write_housing(const model::HousingSolid& housing, const model::Pose3& T_link_housing,
                   std::ostream& out) {
  const std::string origin = "<origin xyz=\"" + triple(T_link_housing.translation()) + "\" rpy=\"" +
                             triple(model::rpy_from_rotation(T_link_housing.linear())) + "\"/>";
  const std::string geometry = housing.shape == model::HousingShape::box
                                   ? "<box size=\"" + triple(housing.size) + "\"/>"
                                   : "<cylinder radius=\"" + xacro_number(housing.radius()) +
                                         "\" length=\"" + xacro_number(housing.size.z()) + "\"/>";
  for (const char* element : {"visual", "collision"}) {
    out << "      <" << element << ">" << origin << "<geometry>" << geometry << "</geometry></"
        << element << ">\n";
  }
}

}  // namespace

std::string sensors_xacro_text(const deploy::SensorFrames& frames, const std::string& header) {
  // The parent is a default in the macro's whitespace-separated params.
  if (frames.parent.empty() || frames.parent.find_first_of(" \t\r\n") != std::string::npos ||
      frames.parent.find(":=") != std::string::npos) {
    throw model::InputError(model::Diagnostic{
        {"(command line)", 0, 0},
        "--parent",
        "'" + frames.parent + "' cannot be the macro's default parent (a space or ':=' in it)",
        "a link name without spaces, e.g. base_link"});
  }
  std::ostringstream out;
  out << "<?xml version=\"1.0\"?>\n<!--\n";
  out << io::xml_comment_lines(header, "  ");
  out << "  Use: <xacro:include filename=\"sensors.urdf.xacro\"/> <xacro:rig_sensors/>\n"
         "  Joint origins are relative to the link `"
      << io::xml_comment_line(frames.parent)
      << "`: pass another `parent` only if it\n"
         "  coincides with it. Mounts placed on a link of the description use that link:\n"
         "  nothing is added for them but a camera's optical frame where the description has\n"
         "  none. Lidars and scanners: the driver's frame_id is the sensor's link (x forward,\n"
         "  z up). Cameras: images and depth clouds in the optical frame (z forward, x right,\n"
         "  y down, REP-103). `prefix` goes before every added name, not the description's.\n"
         "-->\n";
  out << "<robot xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n";
  out << "  <xacro:macro name=\"rig_sensors\" params=\"parent:=" << io::xacro_literal(frames.parent)
      << " prefix:=${''}\">\n";
  for (const deploy::SensorFrame& frame : frames.frames) {
    out << "    <!-- "
        << io::xml_comment_line(
               frame.mount_id + ": " + frame.sensor_id + ", mode " + frame.mode_id +
               (frame.joint.empty() ? "; on the description's link " + frame.link : std::string()))
        << " -->\n";
    // A link the description has is neither written again nor prefixed.
    const std::string link = frame.joint.empty() ? io::xacro_literal(frame.link)
                                                 : "${prefix}" + io::xacro_literal(frame.link);
    if (!frame.joint.empty()) {
      const model::Vec3 rpy = model::rpy_from_rotation(frame.T_parent_link.linear());
      if (frame.housing) {
        out << "    <link name=\"" << link << "\">\n";
        write_housing(*frame.housing, frame.T_link_housing, out);
        out << "    </link>\n";
      } else {
        out << "    <link name=\"" << link << "\"/>\n";
      }
      out << "    <joint name=\"${prefix}" << io::xacro_literal(frame.joint)
          << "\" type=\"fixed\">\n";
      out << "      <parent link=\"${parent}\"/>\n";
      out << "      <child link=\"" << link << "\"/>\n";
      out << "      <origin xyz=\"" << triple(frame.T_parent_link.translation()) << "\" rpy=\""
          << triple(rpy) << "\"/>\n";
      out << "    </joint>\n";
    }
    if (frame.optical_frame && !frame.optical_joint.empty()) {
      const model::Vec3 optical = model::rpy_from_rotation(model::T_sensor_optical().linear());
      out << "    <link name=\"${prefix}" << io::xacro_literal(*frame.optical_frame) << "\"/>\n";
      out << "    <joint name=\"${prefix}" << io::xacro_literal(frame.optical_joint)
          << "\" type=\"fixed\">\n";
      out << "      <parent link=\"" << link << "\"/>\n";
      out << "      <child link=\"${prefix}" << io::xacro_literal(*frame.optical_frame) << "\"/>\n";
      out << "      <origin xyz=\"0 0 0\" rpy=\"" << triple(optical) << "\"/>\n";
      out << "    </joint>\n";
    }
  }
  out << "  </xacro:macro>\n</robot>\n";
  return out.str();
}

}  // namespace rigdesign::deploy
