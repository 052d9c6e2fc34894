#pragma once
/// Ground truth for the KPIs: emitter positions and gas artifacts.
#include <string>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign {

struct EmitterTruth {
  std::string bssid;
  Vec3 position;  ///< [m], map frame
};

/// CSV with header `bssid,x,y,z` (columns in any order), one emitter per line. Errors name
/// file:line:column like the log readers.
std::vector<EmitterTruth> parse_emitter_truth(const std::string& text, const std::string& file);
std::vector<EmitterTruth> read_emitter_truth(const std::string& path);
std::string to_emitter_truth_csv(const std::vector<EmitterTruth>& truth);

/// An artifact of a DARPA SubT ground-truth file (`gt_*.json`: {"artifacts": [{id, type, x, y,
/// z}]}), e.g. type "gas" or "cell phone".
struct Artifact {
  int id = 0;
  std::string type;
  Vec3 position;  ///< [m], course frame
};

/// Reads the artifact list (JSON, read with the YAML parser, which accepts it); InputError
/// naming line and column on a missing or mistyped key.
std::vector<Artifact> read_artifacts(const std::string& path);

}  // namespace rigdesign
