#pragma once
#include <string>

#include "rigdesign/model/rig.hpp"

namespace rigdesign::io {

/// Which sensors.yaml a rig uses, first match wins: `explicit_path` (the --sensors option);
/// the rig's own `sensor_library` field, relative to the rig file; a sensors.yaml in the
/// rig's folder or any folder above it (a repository of rigs keeps its own library); the
/// library bundled with rigdesign.
std::string locate_sensor_library(const model::Rig& rig, const std::string& explicit_path);

/// `relative` resolved against the folder of `file` (absolute paths are kept).
std::string resolve_beside(const std::string& file, const std::string& relative);

/// The folder of rigdesign's bundled data (sensors.yaml, rigs/): $RIGDESIGN_DATA_DIR when set,
/// else share/rigdesign beside the folder of the running executable (bin/ when installed, the
/// build tree's src/ and tests/, where CMake links share/rigdesign to the sources). Never a
/// path compiled in, so an installed prefix can move.
std::string bundled_data_folder();

/// The bundled sensors.yaml: bundled_data_folder()/sensors.yaml. Throws model::InputError
/// naming the places it looked when there is none.
std::string bundled_sensor_library();

}  // namespace rigdesign::io
