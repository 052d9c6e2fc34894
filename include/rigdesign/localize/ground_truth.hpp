#pragma once
/// Ground truth for the KPIs: emitter positions and gas artifacts.
#include <string>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::localize {

struct EmitterTruth {
  std::string bssid;
  model::Vec3 position;  ///< [m], map frame
};

/// An artifact of a DARPA SubT ground-truth file (`gt_*.json`: {"artifacts": [{id, type, x, y,
/// z}]}), e.g. type "gas" or "cell phone".
struct Artifact {
  int id = 0;
  std::string type;
  model::Vec3 position;  ///< [m], course frame
};

}  // namespace rigdesign::localize
