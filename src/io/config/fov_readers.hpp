#pragma once
// A sensor mode's `fov` map: its `shape` names one reader, which reads that shape's angles.
// A new model::FovShape gets its reader here, in kFovReaders.
#include "rigdesign/io/config/yaml_reader.hpp"
#include "rigdesign/model/fov_shape.hpp"

namespace rigdesign::io {

/// The field of view in `fov` (a mode's `fov:` map); findings are recorded on the reader, and
/// a default (empty) field of view is returned when the shape is missing or unknown.
model::FieldOfView read_fov(MapReader& fov);

}  // namespace rigdesign::io
