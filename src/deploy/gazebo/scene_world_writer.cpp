#include "rigdesign/deploy/gazebo/scene_world_writer.hpp"

#include <sstream>

#include "rigdesign/io/emit/xml_emit.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/rotation.hpp"

namespace rigdesign::deploy {

std::string scene_obj_text(const model::Scene& scene, const std::string& header) {
  const model::TriangleMesh mesh = scene.at(0.0);
  std::ostringstream out;
  std::istringstream lines(header);
  for (std::string line; std::getline(lines, line);) out << "# " << line << '\n';
  out << "# " << scene.name << " at t = 0: " << mesh.vertices.size() << " vertices, "
      << mesh.triangles.size() << " triangles, world frame (z up, floor at 0), metres\n";
  for (const model::Vec3& v : mesh.vertices) {
    out << "v " << model::exact_number(v.x()) << ' ' << model::exact_number(v.y()) << ' '
        << model::exact_number(v.z()) << '\n';
  }
  // OBJ indices count from 1.
  for (const std::array<int, 3>& t : mesh.triangles)
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  return out.str();
}

std::string gazebo_world_text(const model::Scene& scene, const std::string& mesh_file,
                              const std::string& header) {
  const model::Vec3 xyz = scene.T_world_robot.translation();
  const model::Vec3 rpy = model::rpy_from_rotation(scene.T_world_robot.linear());
  std::ostringstream start;
  start << model::exact_number(xyz.x()) << ' ' << model::exact_number(xyz.y()) << ' '
        << model::exact_number(xyz.z()) << ' ' << model::exact_number(rpy.x()) << ' '
        << model::exact_number(rpy.y()) << ' ' << model::exact_number(rpy.z());
  std::ostringstream out;
  out << "<?xml version=\"1.0\"?>\n<!--\n"
      << io::xml_comment_lines(header, "  ")
      << "  gz sim world.sdf; then spawn the robot (its URDF with sensors.urdf.xacro and\n"
         "  sensors.gazebo.xacro expanded) at the scene's start pose, x y z roll pitch yaw:\n"
      << "  " << io::xml_comment_line(start.str()) << "\n"
      << "  e.g. ros2 run ros_gz_sim create -topic robot_description -x "
      << model::exact_number(xyz.x()) << " -y " << model::exact_number(xyz.y()) << " -Y "
      << model::exact_number(rpy.z()) << "\n-->\n";
  const std::string name = io::xml_attribute(scene.name);
  out << "<sdf version=\"1.9\">\n"
      << "  <world name=\"" << name << "\">\n"
      << "    <plugin filename=\"gz-sim-physics-system\" name=\"gz::sim::systems::Physics\"/>\n"
      << "    <plugin filename=\"gz-sim-scene-broadcaster-system\" "
         "name=\"gz::sim::systems::SceneBroadcaster\"/>\n"
      << "    <!-- renders gpu_lidar and depth_camera sensors -->\n"
      << "    <plugin filename=\"gz-sim-sensors-system\" name=\"gz::sim::systems::Sensors\">\n"
      << "      <render_engine>ogre2</render_engine>\n"
      << "    </plugin>\n"
      << "    <light type=\"directional\" name=\"sun\">\n"
      << "      <pose>0 0 10 0 0 0</pose>\n"
      << "      <direction>-0.5 0.1 -0.9</direction>\n"
      << "    </light>\n"
      << "    <model name=\"" << name << "_scene\">\n"
      << "      <static>true</static>\n"
      << "      <link name=\"scene\">\n";
  for (const char* element : {"visual", "collision"}) {
    out << "        <" << element << " name=\"" << element << "\">\n"
        << "          <geometry><mesh><uri>" << io::xml_attribute(mesh_file)
        << "</uri></mesh></geometry>\n"
        << "        </" << element << ">\n";
  }
  out << "      </link>\n    </model>\n  </world>\n</sdf>\n";
  return out.str();
}

}  // namespace rigdesign::deploy
