#include "rigdesign/metrics/requirement_check.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "rigdesign/metrics/sector_blame.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::metrics {
namespace {

// Body dimensions agree when within this [m]: files round to millimetres.
constexpr double kBodyTolerance = 1e-3;

RequirementResult named(std::string id, std::string title, std::string field, std::string metric,
                        std::string unit, model::SourceLocation where) {
  RequirementResult result;
  result.id = std::move(id);
  result.title = std::move(title);
  result.field = std::move(field);
  result.metric = std::move(metric);
  result.unit = std::move(unit);
  result.where = std::move(where);
  return result;
}

Verdict verdict(bool pass) {
  return pass ? Verdict::pass : Verdict::fail;
}

// R3's rate, R4 and R5 each bound F from below; each is reported on its own so the binding
// one is visible.
RequirementResult minimum_frequency(RequirementResult result, double required,
                                    const std::string& derivation,
                                    const ResultantMetrics& metrics) {
  result.required = required;
  result.bound = Bound::at_least;
  result.actual = metrics.frequency.value;
  result.verdict = verdict(metrics.frequency.value >= required);
  result.limiting_mounts = metrics.frequency.mounts;
  result.explanation = "F >= " + derivation + " = " + model::format_number(required, 4) + " Hz";
  return result;
}

void check_body(const model::Rig& rig, const model::Requirements& requirements,
                std::vector<RequirementResult>& results) {
  if (!requirements.body_radius || !requirements.body_height) return;
  RequirementResult result = named("R1", "body size", "body", "body", "m", requirements.body_where);
  result.verdict =
      verdict(std::abs(rig.body.radius - *requirements.body_radius) <= kBodyTolerance &&
              std::abs(rig.body.height - *requirements.body_height) <= kBodyTolerance);
  result.explanation =
      "rig body r = " + model::format_number(rig.body.radius) +
      " m, h = " + model::format_number(rig.body.height) +
      " m must match the application's r = " + model::format_number(*requirements.body_radius) +
      " m, h = " + model::format_number(*requirements.body_height) + " m";
  results.push_back(std::move(result));
}

std::string percent(double share) {
  return model::format_number(share * 100, 4) + " %";
}

// The mount a sector's verdict rests on (issue 39: CI annotations go to its line): at the
// angle of the binding share's minimum, the mount that sees most of that share there; when no
// mount sees anything there, the one seeing the nearest angle (the one to turn towards it).
// Nothing without any mount seeing anything.
std::optional<std::size_t> sector_limiting_mount(const RigCoverage& coverage, double theta,
                                                 bool floor) {
  const auto share = [&](const AngleCoverage& angle, std::size_t m) {
    const std::vector<double>& shares = floor ? angle.mount_floor : angle.mount_complete;
    return m < shares.size() ? shares[m] : 0.0;
  };
  const auto best_at = [&](const AngleCoverage& angle) -> std::optional<std::size_t> {
    std::optional<std::size_t> best;
    for (std::size_t m = 0; m < coverage.mount_ids.size(); ++m) {
      if (share(angle, m) > 0 && (!best || share(angle, m) > share(angle, *best))) best = m;
    }
    return best;
  };
  const auto at =
      std::min_element(coverage.angles.begin(), coverage.angles.end(),
                       [&](const AngleCoverage& x, const AngleCoverage& y) {
                         return std::abs(std::remainder(x.theta - theta, 2 * std::numbers::pi)) <
                                std::abs(std::remainder(y.theta - theta, 2 * std::numbers::pi));
                       });
  if (at == coverage.angles.end()) return std::nullopt;
  if (auto best = best_at(*at)) return best;
  const std::size_t n = coverage.angles.size();
  const auto start = static_cast<std::size_t>(at - coverage.angles.begin());
  for (std::size_t step = 1; step <= n / 2; ++step) {
    for (const std::size_t a : {(start + step) % n, (start + n - step) % n}) {
      if (auto best = best_at(coverage.angles[a])) return best;
    }
  }
  return std::nullopt;
}

void check_sectors(const model::Rig& rig, const model::Requirements& requirements,
                   const RigCoverage* coverage, const model::SensorLibrary* library,
                   std::vector<RequirementResult>& results) {
  for (std::size_t i = 0; i < requirements.sectors.size(); ++i) {
    const model::SectorRequirement& sector = requirements.sectors[i];
    RequirementResult result = named("R2", "direction of motion: " + sector.name,
                                     "sectors." + sector.name, "SC", "", sector.where);
    if (coverage == nullptr || i >= coverage->sectors.size()) {
      result.verdict = Verdict::not_evaluated;
      result.explanation = "spatial coverage was not computed";
      results.push_back(std::move(result));
      continue;
    }
    const SectorCoverage& measured = coverage->sectors[i];
    // The verdict rests on the tighter of SC complete and SC floor; that one is reported.
    const BindingShare binding = binding_share(measured);
    if (binding.floor) result.metric = "SC floor";
    result.required = binding.required;
    result.bound = Bound::at_least;
    result.actual = binding.actual;
    result.verdict = verdict(measured.pass);
    const double binding_theta =
        binding.floor ? measured.floor.min_theta : measured.complete.min_theta;
    std::string hidden_by_body;
    const SectorBlame blame = library != nullptr
                                  ? sector_blame(rig, *library, binding_theta, binding.floor)
                                  : SectorBlame{};
    if (blame.mount) {
      result.limiting_mounts = {rig.mounts[*blame.mount].id};
      result.rig_where = blame.where;
      if (blame.body) {
        const std::string hider =
            blame.by_housing ? "the " + blame.part
                             : "the body" + (blame.part.empty() ? "" : " (" + blame.part + ")");
        hidden_by_body = "; at " + model::format_number(model::rad_to_deg(binding_theta), 4) +
                         " deg " + hider + " hides " + percent(blame.hidden) + " of what " +
                         rig.mounts[*blame.mount].id + " would see";
      }
    } else if (const auto limiting = sector_limiting_mount(*coverage, binding_theta, binding.floor);
               limiting && *limiting < rig.mounts.size()) {
      const model::Mount& mount = rig.mounts[*limiting];
      result.limiting_mounts = {mount.id};
      result.rig_where = mount.pose_where.file.empty() ? mount.where : mount.pose_where;
    }
    result.explanation = "over " + model::format_number(model::rad_to_deg(sector.from)) + ".." +
                         model::format_number(model::rad_to_deg(sector.to)) +
                         " deg: SC complete min " + percent(measured.complete.min) + " (at " +
                         model::format_number(model::rad_to_deg(measured.complete.min_theta), 4) +
                         " deg) >= " + percent(sector.min_complete_coverage) + ", SC floor min " +
                         percent(measured.floor.min) + " (at " +
                         model::format_number(model::rad_to_deg(measured.floor.min_theta), 4) +
                         " deg) >= " + percent(sector.min_floor_coverage) + hidden_by_body;
    results.push_back(std::move(result));
  }
}

void check_range(const model::Rig& rig, const model::Requirements& requirements,
                 std::vector<RequirementResult>& results) {
  RequirementResult result =
      named("R3", "range", "range.distance", "d", "m", requirements.range_where);
  result.required = requirements.distance;
  result.bound = Bound::at_least;
  result.actual = rig.distance_of_interest;
  result.verdict = verdict(rig.distance_of_interest + 1e-9 >= requirements.distance);
  result.explanation = "the rig's distance of interest must reach the application's d = " +
                       model::format_number(requirements.distance) + " m";
  results.push_back(std::move(result));
}

void check_frequency(const ResultantMetrics& metrics, const model::Requirements& requirements,
                     std::vector<RequirementResult>& results) {
  if (requirements.min_frequency) {
    results.push_back(minimum_frequency(
        named("R3", "perception rate", "range.min_frequency", "F", "Hz", requirements.range_where),
        *requirements.min_frequency, "the application's rate", metrics));
  }
  if (const auto& dynamics = requirements.object_dynamics) {
    results.push_back(minimum_frequency(
        named("R4", "object dynamics", "object_dynamics", "F", "Hz", dynamics->where),
        dynamics->min_frequency(),
        "v_object / travel = " + model::format_number(dynamics->speed) + " / " +
            model::format_number(dynamics->travel),
        metrics));
  }
  if (const auto& speed = requirements.robot_speed) {
    results.push_back(minimum_frequency(
        named("R5", "robot speed", "robot_speed", "F", "Hz", speed->where), speed->min_frequency(),
        "v / travel = " + model::format_number(speed->speed) + " / " +
            model::format_number(speed->travel),
        metrics));
  }
}

// R6: a ray spacing no wider than the obstacle guarantees a ray hits it at distance d.
void check_resolution(const ResultantMetrics& metrics, const model::Requirements& requirements,
                      std::vector<RequirementResult>& results) {
  if (!requirements.smallest_obstacle) return;
  RequirementResult result = named("R6", "smallest obstacle", "smallest_obstacle.size", "R", "m",
                                   requirements.smallest_obstacle_where);
  result.required = *requirements.smallest_obstacle;
  result.bound = Bound::at_most;
  result.actual = metrics.point_spacing.value;
  result.verdict = verdict(metrics.point_spacing.value <= *requirements.smallest_obstacle);
  result.limiting_mounts = metrics.point_spacing.mounts;
  result.explanation =
      "ray spacing R at the distance of interest must not exceed the smallest "
      "obstacle, " +
      model::format_number(*requirements.smallest_obstacle * 1000, 4) + " mm";
  results.push_back(std::move(result));
}

void check_noise(const ResultantMetrics& metrics, const model::Requirements& requirements,
                 std::vector<RequirementResult>& results) {
  if (!requirements.max_noise) return;
  RequirementResult result =
      named("R7", "accuracy", "accuracy.max_noise", "N", "m", requirements.accuracy_where);
  result.required = *requirements.max_noise;
  result.bound = Bound::at_most;
  result.actual = metrics.noise.value;
  result.verdict = verdict(metrics.noise.value <= *requirements.max_noise);
  result.limiting_mounts = metrics.noise.mounts;
  result.explanation = "range noise N (one sigma) at the distance of interest must not exceed " +
                       model::format_number(*requirements.max_noise * 1000, 4) + " mm";
  results.push_back(std::move(result));
}

void check_lighting(const ResultantMetrics& metrics, const model::Requirements& requirements,
                    std::vector<RequirementResult>& results) {
  if (requirements.lighting.empty()) return;
  RequirementResult result =
      named("R8", "lighting", "lighting", "L", "", requirements.lighting_where);
  std::vector<std::string> names;
  std::vector<std::string> failures;
  for (model::LightCondition condition : requirements.lighting) {
    names.push_back(to_string(condition));
    const LightResult& light = metrics.light_for(condition);
    if (light.immune) continue;
    failures.push_back(to_string(condition) + ": " + model::join(light.failing_mounts));
    result.limiting_mounts.insert(result.limiting_mounts.end(), light.failing_mounts.begin(),
                                  light.failing_mounts.end());
  }
  result.verdict = verdict(failures.empty());
  result.explanation = "every sensor must work in: " + model::join(names);
  if (!failures.empty()) result.explanation += "; not immune: " + model::join(failures);
  results.push_back(std::move(result));
}

// The rig's line behind each verdict not placed already (a sector's, at its limiting mount's
// pose): the first limiting mount's `mode` (the mode sets F, R, N and L), else the rig itself
// (body and distance of interest come from the whole rig).
void locate_in_rig(const model::Rig& rig, std::vector<RequirementResult>& results) {
  for (RequirementResult& result : results) {
    if (!result.rig_where.file.empty()) continue;
    result.rig_where = rig.where;
    if (result.limiting_mounts.empty()) continue;
    for (const model::Mount& mount : rig.mounts) {
      if (mount.id == result.limiting_mounts.front()) {
        result.rig_where = mount.mode_where.file.empty() ? mount.where : mount.mode_where;
        break;
      }
    }
  }
}

}  // namespace

std::optional<double> RequirementResult::margin() const {
  if (!required || !actual) return std::nullopt;
  switch (bound) {
    case Bound::at_least: return *actual - *required;
    case Bound::at_most: return *required - *actual;
    case Bound::none: return std::nullopt;
  }
  return std::nullopt;
}

const model::SourceLocation& RequirementResult::annotated_where() const {
  return rig_where.file.empty() ? where : rig_where;
}

std::vector<RequirementResult> evaluate_requirements(const model::Rig& rig,
                                                     const ResultantMetrics& metrics,
                                                     const model::Requirements& requirements,
                                                     const RigCoverage* coverage,
                                                     const model::SensorLibrary* library) {
  std::vector<RequirementResult> results;
  check_body(rig, requirements, results);
  check_sectors(rig, requirements, coverage, library, results);
  check_range(rig, requirements, results);
  check_frequency(metrics, requirements, results);
  check_resolution(metrics, requirements, results);
  check_noise(metrics, requirements, results);
  check_lighting(metrics, requirements, results);
  locate_in_rig(rig, results);
  return results;
}

std::string to_string(Verdict verdict) {
  switch (verdict) {
    case Verdict::pass: return "pass";
    case Verdict::fail: return "fail";
    case Verdict::not_evaluated: return "not evaluated";
  }
  return "?";
}

}  // namespace rigdesign::metrics
