#pragma once
#include <string>

#include "rigdesign/model/catalog.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::io {

/// Reads a candidate catalog (schema in rigs/README.md). Throws InputError.
model::Catalog load_catalog(const std::string& path);

/// Resolves sensor, mode and slot references against the library: unknown ids, a slot that
/// allows no candidate sensor. Errors only.
model::Diagnostics check_catalog_references(const model::Catalog& catalog,
                                            const model::SensorLibrary& library);

}  // namespace rigdesign::io
