#pragma once
/// The order in which `select` may relax application requirements when the cheapest rig
/// costs too much (paper 1, Fig. 1). Steps act on requirements, never on the satisficing
/// metrics derived from them.
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/model/requirements.hpp"
#include "rigdesign/model/source_location.hpp"

namespace rigdesign::model {

struct RelaxationStep {
  std::string
      requirement;  ///< as written, e.g. "robot_speed.max_speed", "sectors.back.min_floor_coverage"
  std::optional<double> to;            ///< the relaxed value (numeric requirements)
  std::optional<LightCondition> drop;  ///< for `lighting`: the condition no longer required
  SourceLocation where;
};

struct RelaxationPolicy {
  std::string name;
  std::vector<RelaxationStep> steps;
  std::string file;
};

}  // namespace rigdesign::model
