#pragma once
// What `export` (and `select --out`) tell the user about the configuration they wrote.
#include <iosfwd>
#include <string>
#include <vector>

#include "rigdesign/deploy/deployment.hpp"
#include "rigdesign/model/requirements.hpp"
#include "rigdesign/model/rig.hpp"

namespace rigdesign::report {

/// The lines every exported file opens with: what made it and from which files.
std::string deployment_header(const model::Rig& rig, const model::Requirements* requirements);

/// Per mount its frame, observation source and self-filter; the footprint, the Hit Layer's
/// rule and the files written.
void print_deployment(std::ostream& out, const model::Rig& rig,
                      const deploy::Deployment& deployment,
                      const std::vector<std::string>& written);

}  // namespace rigdesign::report
