#include "rigdesign/deploy/ros/self_filters/self_filters_writer.hpp"

#include <sstream>

#include "rigdesign/io/emit/yaml_emit.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::deploy {

std::string self_filters_text(const std::vector<deploy::SelfFilter>& filters,
                              const std::string& box_frame, const model::Pose3& T_robot_box_frame,
                              const std::string& header) {
  std::ostringstream out;
  out << io::yaml_comment(header);
  out << "# 2D scanners: run laser_filters' scan_to_scan_filter_chain as node <mount>_self_filter\n"
         "# with this file; each LaserScanAngularBoundsFilterInPlace drops the scan angles\n"
         "# (laser frame, radians) whose rays hit the robot. 3D sensors: one pcl_ros CropBox\n"
         "# node per box (negative: true drops the inside), chained on the sensor's cloud.\n";
  const model::Pose3 T_frame_robot = T_robot_box_frame.inverse();
  bool any = false;
  for (const deploy::SelfFilter& filter : filters) {
    if (filter.scanner && !filter.bands.empty()) {
      any = true;
      out << io::yaml_scalar(filter.mount_id + "_self_filter") << ":\n  ros__parameters:\n";
      for (std::size_t i = 0; i < filter.bands.size(); ++i) {
        const model::AzimuthBand& band = filter.bands[i];
        out << "    filter" << i + 1 << ":\n";
        out << "      name: "
            << io::yaml_scalar(filter.mount_id + "_robot_" + std::to_string(i + 1)) << "  # "
            << model::format_number(model::rad_to_deg(band.lower), 4) << " to "
            << model::format_number(model::rad_to_deg(band.upper), 4) << " deg\n";
        out << "      type: laser_filters/LaserScanAngularBoundsFilterInPlace\n";
        out << "      params:\n";
        out << "        lower_angle: " << io::yaml_float(band.lower) << '\n';
        out << "        upper_angle: " << io::yaml_float(band.upper) << '\n';
        out << "        replace_with_nan: " << io::yaml_bool(true) << '\n';
      }
    }
    if (!filter.scanner) {
      for (std::size_t i = 0; i < filter.boxes.size(); ++i) {
        any = true;
        const deploy::SelfBox& box = filter.boxes[i];
        // The boxes are axis-aligned in the robot frame; the box frame differs from it by a
        // translation only (the base link's height), so they stay axis-aligned there.
        const model::Vec3 low = T_frame_robot * box.min;
        const model::Vec3 high = T_frame_robot * box.max;
        out << io::yaml_scalar(filter.mount_id + "_self_filter_" + std::to_string(i + 1)) << ":  # "
            << box.part << ", " << box.hits << " rays\n  ros__parameters:\n";
        out << "    input_frame: " << io::yaml_scalar(box_frame) << '\n';
        out << "    min_x: " << io::yaml_float(low.x())
            << "\n    max_x: " << io::yaml_float(high.x()) << '\n';
        out << "    min_y: " << io::yaml_float(low.y())
            << "\n    max_y: " << io::yaml_float(high.y()) << '\n';
        out << "    min_z: " << io::yaml_float(low.z())
            << "\n    max_z: " << io::yaml_float(high.z()) << '\n';
        out << "    negative: true\n    keep_organized: false\n";
      }
    }
  }
  if (!any) out << "# No sensor of this rig sees its own robot: nothing to filter.\n{}\n";
  return out.str();
}

}  // namespace rigdesign::deploy
