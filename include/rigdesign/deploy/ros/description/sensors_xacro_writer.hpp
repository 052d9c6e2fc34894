#pragma once
/// `sensors.urdf.xacro`, as `rigdesign export` writes it: one macro,
/// `<xacro:rig_sensors parent="..." prefix=""/>`, with a link and fixed joint per mount and a
/// camera's optical frame. The robot descriptions it joins are read by
/// io/robot/robot_description_loader.hpp.
#include <string>

#include "rigdesign/deploy/sensor_frames.hpp"

namespace rigdesign::deploy {

/// The file's text; `header` opens it as a comment. Numbers are written so that they read
/// back exactly; names go through the XML attribute escaping.
std::string sensors_xacro_text(const deploy::SensorFrames& frames, const std::string& header);

}  // namespace rigdesign::deploy
