#pragma once
#include <string>

#include "rigdesign/model/requirements.hpp"

namespace rigdesign::io {

/// Reads an application requirements file R1-R8 (schema in rigs/README.md).
/// Throws InputError listing every problem.
model::Requirements load_requirements(const std::string& path);

}  // namespace rigdesign::io
