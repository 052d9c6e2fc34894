// Fuzz target: a robot description as URDF (urdfdom), poses only (meshes are the mesh targets').
#include "fuzz_input.hpp"
#include "rigdesign/io/robot/robot_description_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  rigdesign::io::RobotDescriptionRequest request;
  request.path = rigdesign::fuzz::input_file(data, size, "robot.urdf");
  request.expander = rigdesign::io::RobotDescriptionRequest::Expander::builtin;
  request.load_meshes = false;
  request.named_at = {"rig.yaml", 1, 1};
  return rigdesign::fuzz::expect_input_errors(
      [&] { rigdesign::io::load_robot_description(request); });
}
