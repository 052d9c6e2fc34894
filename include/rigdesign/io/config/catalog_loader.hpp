#pragma once
#include <string>

#include "rigdesign/model/catalog.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign {

/// Reads a candidate catalog (schema in rigs/README.md). Throws InputError.
Catalog load_catalog(const std::string& path);

/// Resolves sensor, mode and slot references against the library: unknown ids, a slot that
/// allows no candidate sensor. Errors only.
Diagnostics check_catalog_references(const Catalog& catalog, const SensorLibrary& library);

}  // namespace rigdesign
