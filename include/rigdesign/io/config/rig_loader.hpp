#pragma once
#include <functional>
#include <string>

#include "rigdesign/io/robot/robot_description_loader.hpp"
#include "rigdesign/model/rig.hpp"

namespace rigdesign::io {

/// Reads a rig file (schema in rigs/README.md). Sensor and mode references are only read
/// here; check_rig_references() resolves them against a library. Throws InputError.
model::Rig load_rig(const std::string& path);

/// Reads the robot description a rig names: load_robot_description when empty, or a caller's
/// copy of one it read before (expanding and loading a description takes seconds).
using DescriptionReader = std::function<model::RobotDescription(const RobotDescriptionRequest&)>;

/// As load_rig, on `text` not (yet) in a file: the rig the file at `path` would hold (its name
/// in messages; the files it names are found beside it). The studio checks each edit with it,
/// its robot description read once (`read_description`).
model::Rig load_rig_text(const std::string& text, const std::string& path,
                         const DescriptionReader& read_description = {});

}  // namespace rigdesign::io
