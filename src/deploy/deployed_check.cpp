#include "rigdesign/deploy/deployed_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::deploy {
namespace {

// Below this an SC difference is rounding of the exact path, not a loss.
constexpr double kLossTolerance = 1e-4;
// A setting that removes more than this of a sector beyond the body is worth a warning. An
// angular self-filter drops whole rays, the free stretch before the body too: the export's
// own filters lose up to 0.015 % of a sector that way (cart_two_scanners), a filter widened
// past the body loses whole degrees (percent).
constexpr double kWarnedLoss = 1e-3;

std::string deployed_percent(double share) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f %%", 100 * share);
  return buffer;
}

metrics::RequirementResult result(std::string id, std::string title, std::string field,
                                  std::string metric, const model::SourceLocation& where) {
  metrics::RequirementResult r;
  r.id = std::move(id);
  r.title = std::move(title);
  r.field = std::move(field);
  r.metric = std::move(metric);
  r.where = where;
  return r;
}

// A limiting setting and what it does to one mount.
struct Setting {
  std::string mount_id;
  model::MountLimits limits;
  model::LimitSetting setting;
};

// The range limits of the nav2 sources that cut into their modes' ranges, and the filters.
std::vector<Setting> settings_of(const model::Rig& rig, const model::SensorLibrary& library,
                                 const DeployedConfig& config) {
  std::vector<Setting> settings;
  for (const DeployedSource& source : config.sources) {
    const auto mount = std::find_if(rig.mounts.begin(), rig.mounts.end(),
                                    [&](const model::Mount& m) { return m.id == source.mount_id; });
    if (mount == rig.mounts.end()) continue;
    const model::SensorMode* mode = &library.resolved_mode(mount->sensor_id, mount->mode_id);
    const costmap::ObservationSource& s = source.source;
    const auto add_range = [&](const char* key, double value, const model::SourceLocation& where,
                               bool minimum) {
      Setting setting{source.mount_id, {}, {}};
      (minimum ? setting.limits.min_range : setting.limits.max_range) = value;
      setting.setting = {source.mount_id + " " + key + " " + model::format_number(value, 4) + " m",
                         where};
      settings.push_back(setting);
    };
    if (s.obstacle_min_range > mode->min_range) {
      add_range("obstacle_min_range", s.obstacle_min_range, source.obstacle_min_range_where, true);
    }
    if (s.obstacle_max_range < mode->max_range) {
      add_range("obstacle_max_range", s.obstacle_max_range, source.obstacle_max_range_where, false);
    }
  }
  for (const DeployedFilter& filter : config.filters) {
    settings.push_back({filter.mount_id, filter.limits, filter.setting});
  }
  return settings;
}

void add_limits(model::MountLimits& into, const model::MountLimits& limits) {
  if (limits.min_range) into.min_range = std::max(into.min_range.value_or(0.0), *limits.min_range);
  if (limits.max_range) {
    into.max_range =
        into.max_range ? std::min(*into.max_range, *limits.max_range) : *limits.max_range;
  }
  into.excluded_azimuths.insert(into.excluded_azimuths.end(), limits.excluded_azimuths.begin(),
                                limits.excluded_azimuths.end());
  into.excluded_boxes.insert(into.excluded_boxes.end(), limits.excluded_boxes.begin(),
                             limits.excluded_boxes.end());
}

model::Rig limited(const model::Rig& rig, const std::vector<const Setting*>& settings) {
  model::Rig copy = rig;
  for (model::Mount& mount : copy.mounts) {
    for (const Setting* setting : settings) {
      if (setting->mount_id == mount.id) add_limits(mount.limits, setting->limits);
    }
  }
  return copy;
}

// SC lost in a sector: the larger of the complete and floor minimum's drops.
double loss(const metrics::SectorCoverage& design, const metrics::SectorCoverage& deployed) {
  return std::max(design.complete.min - deployed.complete.min,
                  design.floor.min - deployed.floor.min);
}

void check_sources(const model::Rig& rig, const model::Requirements& requirements,
                   const DeployedConfig& config, std::vector<metrics::RequirementResult>& results) {
  for (const model::Mount& mount : rig.mounts) {
    const auto source =
        std::find_if(config.sources.begin(), config.sources.end(),
                     [&](const DeployedSource& s) { return s.mount_id == mount.id; });
    metrics::RequirementResult r = result("D1", "observation source for " + mount.id,
                                          "observation_sources", "source", mount.where);
    if (source == config.sources.end()) {
      r.verdict = metrics::Verdict::fail;
      r.limiting_mounts = {mount.id};
      r.explanation = config.nav2_file + " has no observation source named " + mount.id +
                      ": the costmap never sees this sensor";
      results.push_back(r);
      continue;
    }
    r.where = source->where;
    r.explanation = "observation source " + mount.id + " in " + config.nav2_file;
    results.push_back(r);
    const costmap::ObservationSource& s = source->source;
    const double top = rig.body.area_top();
    metrics::RequirementResult band =
        result("D2", "height band of " + mount.id, "max_obstacle_height", "max_obstacle_height",
               source->max_obstacle_height_where);
    band.unit = "m";
    band.required = top;
    band.bound = metrics::Bound::at_least;
    band.actual = s.max_obstacle_height;
    band.limiting_mounts = {mount.id};
    if (s.max_obstacle_height < top - 1e-9) {
      band.verdict = metrics::Verdict::fail;
      band.explanation = "max_obstacle_height " + model::format_number(s.max_obstacle_height, 4) +
                         " m is below the top of the area to perceive (" +
                         model::format_number(top, 4) + " m): obstacles above it never mark";
    } else if (requirements.smallest_obstacle &&
               s.min_obstacle_height >= *requirements.smallest_obstacle) {
      band.field = band.metric = "min_obstacle_height";
      band.where = source->min_obstacle_height_where;
      band.required = *requirements.smallest_obstacle;
      band.bound = metrics::Bound::at_most;
      band.actual = s.min_obstacle_height;
      band.verdict = metrics::Verdict::fail;
      band.explanation = "min_obstacle_height " + model::format_number(s.min_obstacle_height, 4) +
                         " m lets R6's smallest obstacle (" +
                         model::format_number(*requirements.smallest_obstacle, 4) +
                         " m) pass unmarked";
    } else {
      band.explanation = "marks " + model::format_number(s.min_obstacle_height, 4) + ".." +
                         model::format_number(s.max_obstacle_height, 4) +
                         " m, holding the area up to " + model::format_number(top, 4) + " m";
    }
    results.push_back(band);
  }
}

// What `setting` alone removes of each required sector beyond the design's own coverage
// (which already has the robot's shadow, from the same ray cast as the export's
// self-filters): a warning naming the setting and the SC it takes, even when D3 passes.
void warn_if_beyond_body(const model::Rig& rig, const model::SensorLibrary& library,
                         const std::vector<metrics::SectorCoverage>& designed,
                         const std::vector<model::SectorRequirement>& sectors,
                         const Setting& setting, std::vector<model::Diagnostic>& warnings) {
  const metrics::RigCoverage alone =
      metrics::compute_coverage(limited(rig, {&setting}), library, sectors);
  std::string removed;
  for (std::size_t k = 0; k < sectors.size(); ++k) {
    const double own = loss(designed[k], alone.sectors[k]);
    if (own <= kWarnedLoss) continue;
    removed += (removed.empty() ? "" : ", ") + model::format_number(100 * own, 3) + " % of " +
               sectors[k].name;
  }
  if (removed.empty()) return;
  warnings.push_back({setting.setting.where, setting.setting.what,
                      "removes " + removed +
                          " (SC, the larger of complete and floor) beyond the robot's own shadow",
                      "a limit or filter that drops only the robot itself (export writes one)",
                      model::Severity::warning});
}

}  // namespace

DeploymentCheck check_deployment(const model::Rig& rig, const model::SensorLibrary& library,
                                 const model::Requirements& requirements,
                                 const DeployedConfig& config, const metrics::RigCoverage* design) {
  DeploymentCheck check;
  std::vector<metrics::RequirementResult>& results = check.results;
  if (!config.nav2_file.empty()) check_sources(rig, requirements, config, results);
  const std::vector<Setting> settings = settings_of(rig, library, config);
  if (requirements.sectors.empty() || settings.empty()) return check;
  std::vector<const Setting*> all;
  for (const Setting& setting : settings) all.push_back(&setting);
  const metrics::RigCoverage own_design =
      design ? metrics::RigCoverage{}
             : metrics::compute_coverage(rig, library, requirements.sectors);
  const std::vector<metrics::SectorCoverage>& designed = (design ? *design : own_design).sectors;
  const metrics::RigCoverage deployed =
      metrics::compute_coverage(limited(rig, all), library, requirements.sectors);
  for (std::size_t k = 0; k < requirements.sectors.size(); ++k) {
    const metrics::SectorCoverage& before = designed[k];
    const metrics::SectorCoverage& after = deployed.sectors[k];
    metrics::RequirementResult r = result("D3", "deployed coverage: " + before.sector.name,
                                          "sectors", "SC", before.sector.where);
    // The verdict rests on the tighter of SC complete and floor after the limits, unrounded.
    const metrics::BindingShare binding = metrics::binding_share(after);
    if (binding.floor) r.metric = "SC floor";
    r.required = binding.required;
    r.bound = metrics::Bound::at_least;
    r.actual = binding.actual;
    r.explanation = "complete min " + deployed_percent(before.complete.min) + " -> " +
                    deployed_percent(after.complete.min) + ", floor min " +
                    deployed_percent(before.floor.min) + " -> " +
                    deployed_percent(after.floor.min) + " after the deployed limits and filters";
    if (after.pass || !before.pass) {
      if (!before.pass) r.verdict = metrics::Verdict::not_evaluated;
      results.push_back(r);
      continue;
    }
    // Which settings lose coverage here: each one applied alone.
    r.verdict = metrics::Verdict::fail;
    std::string culprits;
    for (const Setting& setting : settings) {
      const metrics::RigCoverage alone =
          metrics::compute_coverage(limited(rig, {&setting}), library, {before.sector});
      const double own = loss(before, alone.sectors.front());
      if (own <= kLossTolerance) continue;
      if (culprits.empty()) r.where = setting.setting.where;
      r.limiting_mounts.push_back(setting.mount_id);
      culprits += "; " + setting.setting.what + " (" + model::to_string(setting.setting.where) +
                  ") loses " + deployed_percent(own);
    }
    r.explanation += ": the sector needs complete " +
                     deployed_percent(before.sector.min_complete_coverage) + " and floor " +
                     deployed_percent(before.sector.min_floor_coverage) + culprits;
    results.push_back(r);
  }
  // One setting alone removes no more than all of them together (each only takes rays away),
  // so when the deployed coverage keeps every sector within the warned loss, none can warn:
  // the per-setting coverage runs are skipped (a passing deployment costs one run, not N + 1).
  bool deployed_loses = false;
  for (std::size_t k = 0; k < requirements.sectors.size(); ++k)
    deployed_loses = deployed_loses || loss(designed[k], deployed.sectors[k]) > kWarnedLoss;
  if (deployed_loses) {
    for (const Setting& setting : settings)
      warn_if_beyond_body(rig, library, designed, requirements.sectors, setting, check.warnings);
  }
  return check;
}

}  // namespace rigdesign::deploy
