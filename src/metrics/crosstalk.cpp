#include "rigdesign/metrics/crosstalk.hpp"

#include <algorithm>
#include <cmath>

#include "rigdesign/model/format_number.hpp"

namespace rigdesign::metrics {
namespace {

std::string nanometres(double wavelength) {
  return model::format_number(wavelength * 1e9, 4) + " nm";
}

std::string microseconds(double seconds) {
  return model::format_number(seconds * 1e6, 4) + " us";
}

// Why the rig's statements keep `a` and `b` apart, or why they do not (empty first: no
// measure stated).
struct Mitigated {
  bool ok = false;
  std::string why;
};

Mitigated mitigation_of(const model::Mount& a, const model::Emitter& light_a, const model::Mount& b,
                        const model::Emitter& light_b) {
  if (!a.crosstalk || !b.crosstalk) return {};
  const model::CrosstalkMitigation& x = *a.crosstalk;
  const model::CrosstalkMitigation& y = *b.crosstalk;
  if (!x.sync_group.empty() && x.sync_group == y.sync_group) {
    for (const auto& [mount, light] : {std::pair{&a, &light_a}, std::pair{&b, &light_b}}) {
      if (!light->supports("sync") && !light->supports("phase_lock"))
        return {false, mount->sensor_id + " supports no hardware sync (sensors.yaml lists " +
                           (light->mitigation.empty() ? std::string("no measure")
                                                      : model::join(light->mitigation)) +
                           ")"};
    }
    const double needed =
        std::max(light_a.min_delay.value_or(0.0), light_b.min_delay.value_or(0.0));
    const double apart = std::abs(x.delay.value_or(0.0) - y.delay.value_or(0.0));
    if (apart + 1e-12 < needed)
      return {false, "sync group '" + x.sync_group + "': captures " + microseconds(apart) +
                         " apart, the sensors need " + microseconds(needed)};
    return {true, "sync group '" + x.sync_group + "'" +
                      (needed > 0 ? ", captures " + microseconds(apart) +
                                        " apart >= " + microseconds(needed)
                                  : std::string())};
  }
  if (x.channel && y.channel) {
    if (!light_a.supports("channels") || !light_b.supports("channels"))
      return {false, "channels stated, but sensors.yaml lists no modulation channels for " +
                         (light_a.supports("channels") ? b.sensor_id : a.sensor_id)};
    if (*x.channel == *y.channel) return {false, "both on channel " + std::to_string(*x.channel)};
    return {true, "channels " + std::to_string(*x.channel) + " and " + std::to_string(*y.channel)};
  }
  return {};
}

// Cameras that light the whole scene at once (ToF, structured light, active stereo), as
// against scanners whose narrow pulses sweep it.
bool floods_scene(const model::SensorLibrary& library, const model::Mount& mount) {
  const model::Sensor* sensor = library.find(mount.sensor_id);
  return sensor != nullptr && (sensor->technology == model::Technology::tof ||
                               sensor->technology == model::Technology::structured_light ||
                               sensor->technology == model::Technology::active_stereo);
}

RequirementResult pair_result(const model::Mount& a, const model::Mount& b,
                              const PairOverlap& pair) {
  RequirementResult result;
  result.id = "D5";
  result.title = "crosstalk: " + a.id + " and " + b.id;
  result.field = "mounts";
  result.metric = "overlap";
  result.unit = "m^2";
  result.required = 0.0;
  result.actual = pair.area;
  result.bound = Bound::at_most;
  result.limiting_mounts = {a.id, b.id};
  // The finding is about the rig alone: it is both where it is stated and where it is mended.
  result.where = a.crosstalk ? a.crosstalk->where : a.where;
  result.also_where = {b.crosstalk ? b.crosstalk->where : b.where};
  return result;
}

}  // namespace

CrosstalkFindings crosstalk_findings(const model::Rig& rig, const model::SensorLibrary& library,
                                     const Covisibility& overlap) {
  CrosstalkFindings findings;
  for (const PairOverlap& pair : overlap.pairs) {
    if (pair.area <= 0) continue;
    const model::Mount& a = rig.mounts[pair.a];
    const model::Mount& b = rig.mounts[pair.b];
    const model::SensorMode& mode_a = library.resolved_mode(a.sensor_id, a.mode_id);
    const model::SensorMode& mode_b = library.resolved_mode(b.sensor_id, b.mode_id);
    if (!mode_a.emitter || !mode_b.emitter) continue;  // a passive sensor lights nothing
    const model::Emitter& light_a = *mode_a.emitter;
    const model::Emitter& light_b = *mode_b.emitter;
    if (light_a.wavelength && light_b.wavelength &&
        std::abs(*light_a.wavelength - *light_b.wavelength) > kFilterPassband)
      continue;
    const std::string shared = "they share " + model::format_number(pair.area, 3) + " m^2 within " +
                               model::format_number(overlap.distance, 3) + " m (floor " +
                               model::format_number(pair.floor_area, 3) + " m^2)" +
                               (light_a.wavelength && light_b.wavelength
                                    ? ", emitters at " + nanometres(*light_a.wavelength) + " and " +
                                          nanometres(*light_b.wavelength)
                                    : std::string());
    const Mitigated measure = mitigation_of(a, light_a, b, light_b);
    // The vendors' statements are about several units of their own sensor: they judge a pair of
    // one model. Two models are judged only when both flood a scene with light (cameras), and
    // then no statement covers them: a warning unless the rig states a measure.
    const bool same_model = a.sensor_id == b.sensor_id;
    if (!same_model && !(floods_scene(library, a) && floods_scene(library, b))) continue;
    const bool interferes = same_model && light_a.crosstalk == model::Crosstalk::interferes;
    const bool immune = same_model && light_a.crosstalk == model::Crosstalk::immune;
    if (!interferes && !immune && !measure.ok) {
      findings.warnings.emplace_back(
          a.where, "mounts",
          a.id + " (" + a.sensor_id + ") and " + b.id + " (" + b.sensor_id +
              ") light each other: " + shared + "; " +
              (same_model ? "sensors.yaml has no vendor statement on crosstalk between two of them"
                          : "no vendor statement covers two different cameras") +
              (measure.why.empty() ? std::string() : "; " + measure.why),
          "a test on the robot, or a `crosstalk:` measure on both mounts",
          model::Severity::warning);
      continue;
    }
    RequirementResult result = pair_result(a, b, pair);
    if (immune) {
      result.explanation =
          shared + "; both vendors state units do not interfere (" + light_a.source + ")";
      result.verdict = Verdict::pass;
    } else if (measure.ok) {
      result.explanation = shared + "; kept apart by " + measure.why;
      result.verdict = Verdict::pass;
    } else {
      result.explanation =
          shared + "; " +
          (light_a.source.empty() ? std::string("its vendor says units interfere")
                                  : "units interfere (" + light_a.source + ")") +
          (measure.why.empty() ? "; state `crosstalk: {sync, delay_us}` or `{channel}` on both "
                                 "mounts, or turn one so that they share nothing"
                               : "; " + measure.why);
      result.verdict = Verdict::fail;
    }
    findings.verdicts.push_back(std::move(result));
  }
  return findings;
}

CrosstalkFindings crosstalk_findings(const model::Rig& rig, const model::SensorLibrary& library) {
  return crosstalk_findings(rig, library, covisibility(rig, library, covisibility_distance(rig)));
}

}  // namespace rigdesign::metrics
