#include "rigdesign/deploy/ros/self_filters/self_filters_launch_writer.hpp"

#include <sstream>

#include "rigdesign/io/emit/python_emit.hpp"

namespace rigdesign::deploy {
namespace {

// ("from", "to") remapping pairs as a Python list.
std::string remappings(const std::vector<std::pair<std::string, std::string>>& pairs) {
  std::string text = "[";
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    text += (i ? ", (" : "(") + io::python_string(pairs[i].first) + ", " +
            io::python_string(pairs[i].second) + ")";
  }
  return text + "]";
}

void write_scanner_chain(std::ostringstream& out, const deploy::SelfFilter& filter,
                         const deploy::SourceConfig& source) {
  out << "        Node(\n"
      << "            package='laser_filters',\n"
      << "            executable='scan_to_scan_filter_chain',\n"
      << "            name=" << io::python_string(filter.mount_id + "_self_filter") << ",\n"
      << "            parameters=[PARAMETERS],\n"
      << "            remappings="
      << remappings({{"scan", source.raw_topic}, {"scan_filtered", source.topic}}) << ",\n"
      << "        ),\n";
}

void write_crop_boxes(std::ostringstream& out, const deploy::SelfFilter& filter,
                      const deploy::SourceConfig& source) {
  const std::size_t n = filter.boxes.size();
  for (std::size_t k = 1; k <= n; ++k) {
    const std::string input =
        k == 1 ? source.raw_topic : deploy::crop_box_topic(source.raw_topic, k - 1, n);
    out << "                ComposableNode(\n"
        << "                    package='pcl_ros',\n"
        << "                    plugin='pcl_ros::CropBox',\n"
        << "                    name="
        << io::python_string(filter.mount_id + "_self_filter_" + std::to_string(k)) << ",\n"
        << "                    parameters=[PARAMETERS],\n"
        << "                    remappings="
        << remappings(
               {{"input", input}, {"output", deploy::crop_box_topic(source.raw_topic, k, n)}})
        << ",\n"
        << "                ),\n";
  }
}

}  // namespace

std::string self_filters_launch_text(const std::vector<deploy::SelfFilter>& filters,
                                     const std::vector<deploy::SourceConfig>& sources,
                                     const std::string& params_file, const std::string& header) {
  std::ostringstream out;
  out << io::python_comment(header);
  out << "#\n"
      << io::python_comment(
             "Starts the self-filters of " + params_file +
             " on the drivers' topics; the nav2 observation sources read their outputs.")
      << "# 2D scanners: laser_filters scan_to_scan_filter_chain (Humble and Jazzy).\n"
         "# 3D sensors: pcl_ros::CropBox components, which pcl_ros releases for Jazzy only\n"
         "# (Humble: build perception_pcl's ros2 branch from source).\n"
         "# ros2 launch self_filters.launch.py\n"
         "import os\n\n"
         "from launch import LaunchDescription\n"
         "from launch_ros.actions import ComposableNodeContainer, Node\n"
         "from launch_ros.descriptions import ComposableNode\n\n"
         "PARAMETERS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "
      << io::python_string(params_file) << ")\n\n\n"
      << "def generate_launch_description():\n"
      << "    return LaunchDescription([\n";
  bool any_boxes = false;
  for (std::size_t m = 0; m < filters.size() && m < sources.size(); ++m) {
    if (filters[m].scanner && deploy::filters_anything(filters[m]))
      write_scanner_chain(out, filters[m], sources[m]);
    any_boxes = any_boxes || (!filters[m].scanner && deploy::filters_anything(filters[m]));
  }
  if (any_boxes) {
    out << "        ComposableNodeContainer(\n"
        << "            name='rigdesign_self_filters',\n"
        << "            namespace='',\n"
        << "            package='rclcpp_components',\n"
        << "            executable='component_container',\n"
        << "            composable_node_descriptions=[\n";
    for (std::size_t m = 0; m < filters.size() && m < sources.size(); ++m) {
      if (!filters[m].scanner && deploy::filters_anything(filters[m]))
        write_crop_boxes(out, filters[m], sources[m]);
    }
    out << "            ],\n"
        << "        ),\n";
  }
  out << "    ])\n";
  return out.str();
}

}  // namespace rigdesign::deploy
