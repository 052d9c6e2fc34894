#include "rigdesign/model/rotation.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"

using namespace rigdesign;

namespace {
bool near(const model::Vec3& a, const model::Vec3& b) {
  return (a - b).norm() < 1e-12;
}
}  // namespace

TEST_CASE("rpy follows URDF: positive pitch looks down, positive yaw turns left") {
  // Ry(+90 deg) maps x to (cos 90, 0, -sin 90) = -z: a camera pitched +90 deg looks at the floor.
  CHECK(near(model::rotation_from_rpy(0, model::deg_to_rad(90), 0) * model::Vec3::UnitX(),
             -model::Vec3::UnitZ()));
  // Rz(+90 deg) maps x to y: yaw +90 deg faces the robot's left.
  CHECK(near(model::rotation_from_rpy(0, 0, model::deg_to_rad(90)) * model::Vec3::UnitX(),
             model::Vec3::UnitY()));
}

TEST_CASE("rpy applies roll first, then pitch, then yaw about fixed axes") {
  // R = Rz(90) * Rx(90): y -> Rx -> z -> Rz -> z. The other order (Rx * Rz) would give -x.
  const model::Mat3 rotation =
      model::rotation_from_rpy(model::deg_to_rad(90), 0, model::deg_to_rad(90));
  CHECK(near(rotation * model::Vec3::UnitY(), model::Vec3::UnitZ()));
  CHECK(near(rotation * model::Vec3::UnitX(), model::Vec3::UnitY()));
}

TEST_CASE("pose_from_xyz_rpy maps sensor-frame points into the robot frame") {
  const model::Pose3 T_robot_sensor = model::pose_from_xyz_rpy(
      model::Vec3(0.46, 0.0, 0.75), model::Vec3(0, 0, model::deg_to_rad(180)));
  // A point 1 m ahead of a backward-facing sensor lies 1 m behind the sensor in the robot frame.
  CHECK(near(T_robot_sensor * model::Vec3(1, 0, 0), model::Vec3(-0.54, 0.0, 0.75)));
}

TEST_CASE("rpy_from_rotation inverts rotation_from_rpy") {
  for (const model::Vec3& rpy_deg :
       {model::Vec3(0, 25, 0), model::Vec3(0, 20, -90), model::Vec3(10, -35, 170),
        model::Vec3(-5, 0, 180), model::Vec3(30, 60, -120)}) {
    const model::Vec3 rpy(model::deg_to_rad(rpy_deg.x()), model::deg_to_rad(rpy_deg.y()),
                          model::deg_to_rad(rpy_deg.z()));
    const model::Mat3 rotation = model::rotation_from_rpy(rpy.x(), rpy.y(), rpy.z());
    const model::Vec3 back = model::rpy_from_rotation(rotation);
    CHECK(model::rotation_from_rpy(back.x(), back.y(), back.z()).isApprox(rotation, 1e-12));
  }
  // At pitch 90 deg only one rotation about the vertical is defined.
  const model::Mat3 gimbal =
      model::rotation_from_rpy(0, model::deg_to_rad(90), model::deg_to_rad(30));
  const model::Vec3 back = model::rpy_from_rotation(gimbal);
  CHECK(model::rotation_from_rpy(back.x(), back.y(), back.z()).isApprox(gimbal, 1e-9));
}

TEST_CASE("a negative zero (a rotation's rounding) prints as 0, other numbers keep their sign") {
  const double negative_zero = -0.0;
  CHECK(std::signbit(negative_zero));
  CHECK(model::format_number(negative_zero) == "0");
  CHECK(model::exact_number(negative_zero) == "0");
  CHECK(model::format_number(-1e-20, 3) == "-1e-20");
  CHECK(model::exact_number(-0.5) == "-0.5");
}
