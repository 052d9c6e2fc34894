#pragma once
/// `check` on what the stack will do with the rig (issue 14 item 2): given the nav2
/// observation sources and the self-filters a deployment runs, it fails when a range limit or
/// a filter removes part of a required sector's volume or floor (the SC lost per sector and
/// the settings that lose it, with their file:line), when a source's height band misses the
/// area to perceive (or lets R6's smallest obstacle through), or when a mount has no source.
#include <string>
#include <vector>

#include "rigdesign/costmap/observation.hpp"
#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/metrics/requirement_check.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/mount_limits.hpp"
#include "rigdesign/model/requirements.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::deploy {

/// One nav2 observation source as deployed, with where its settings are written.
struct DeployedSource {
  std::string mount_id;
  costmap::ObservationSource source;
  model::SourceLocation where;  ///< the source's map
  model::SourceLocation obstacle_min_range_where;
  model::SourceLocation obstacle_max_range_where;
  model::SourceLocation min_obstacle_height_where;
  model::SourceLocation max_obstacle_height_where;
};

/// One filter of a mount's data (a laser_filters entry, a crop box): what it drops.
struct DeployedFilter {
  std::string mount_id;
  model::MountLimits limits;
  model::LimitSetting setting;
};

struct DeployedConfig {
  std::string nav2_file;  ///< empty: no nav2 parameters given (sources are not checked)
  std::vector<DeployedSource> sources;
  std::vector<DeployedFilter> filters;
  /// What the files hold that the stack may refuse but rigdesign can still check (a layer
  /// class outside nav2 and STVL), for the report's warnings.
  std::vector<model::Diagnostic> warnings;
};

/// The verdicts on a deployment, and what it does that the verdicts let pass.
struct DeploymentCheck {
  std::vector<metrics::RequirementResult> results;
  /// A range limit or filter removing part of a required sector beyond the robot's own
  /// shadow (how much of each), at the setting's file:line: a warning even when D3 passes.
  std::vector<model::Diagnostic> warnings;
};

/// Results with ids D1 (every mount has an observation source), D2 (each source's height
/// band holds the area to perceive and marks R6's smallest obstacle) and D3 (per requirement
/// sector: the deployed coverage still meets it, judged on the tighter of SC complete and SC
/// floor, unrounded; on failure the SC lost and each setting that loses some of it, with
/// file:line). Precondition: the rig's references resolve. `design`: the rig's own coverage
/// for requirements.sectors when the caller has it (check computes it for R2), else null and
/// it is computed here.
DeploymentCheck check_deployment(const model::Rig& rig, const model::SensorLibrary& library,
                                 const model::Requirements& requirements,
                                 const DeployedConfig& config,
                                 const metrics::RigCoverage* design = nullptr);

}  // namespace rigdesign::deploy
