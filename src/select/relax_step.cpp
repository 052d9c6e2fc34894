#include "rigdesign/select/relax_step.hpp"

#include <algorithm>
#include <functional>

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::select {
namespace {

// A relaxable number: where it lives in the requirements, its unit, which way is looser
// and its allowed range.
struct Relaxable {
  std::function<double*(model::Requirements&)> value;  // nullptr when the requirements omit it
  std::string unit;
  bool looser_is_larger;
  double low;
  double high;
};

std::optional<Relaxable> relaxable(const std::string& path) {
  const auto motion = [](std::optional<model::MotionBetweenFrames> model::Requirements::*member,
                         double model::MotionBetweenFrames::*field) {
    return [member, field](model::Requirements& r) -> double* {
      return (r.*member) ? &((*(r.*member)).*field) : nullptr;
    };
  };
  const auto optional_number = [](std::optional<double> model::Requirements::*field) {
    return
        [field](model::Requirements& r) -> double* { return (r.*field) ? &*(r.*field) : nullptr; };
  };
  constexpr double kHuge = 1e9;
  if (path == "robot_speed.max_speed") {
    return Relaxable{motion(&model::Requirements::robot_speed, &model::MotionBetweenFrames::speed),
                     "m/s", false, 0, kHuge};
  }
  if (path == "robot_speed.max_travel_between_frames") {
    return Relaxable{motion(&model::Requirements::robot_speed, &model::MotionBetweenFrames::travel),
                     "m", true, 0, kHuge};
  }
  if (path == "object_dynamics.max_object_speed") {
    return Relaxable{
        motion(&model::Requirements::object_dynamics, &model::MotionBetweenFrames::speed), "m/s",
        false, 0, kHuge};
  }
  if (path == "object_dynamics.max_travel_between_frames") {
    return Relaxable{
        motion(&model::Requirements::object_dynamics, &model::MotionBetweenFrames::travel), "m",
        true, 0, kHuge};
  }
  if (path == "range.min_frequency") {
    return Relaxable{optional_number(&model::Requirements::min_frequency), "Hz", false, 0, kHuge};
  }
  if (path == "range.distance") {
    return Relaxable{[](model::Requirements& r) { return &r.distance; }, "m", false, 0, kHuge};
  }
  if (path == "smallest_obstacle.size") {
    return Relaxable{optional_number(&model::Requirements::smallest_obstacle), "m", true, 0, kHuge};
  }
  if (path == "accuracy.max_noise") {
    return Relaxable{optional_number(&model::Requirements::max_noise), "m", true, 0, kHuge};
  }
  const std::string prefix = "sectors.";
  if (path.rfind(prefix, 0) == 0) {
    const std::size_t dot = path.rfind('.');
    const std::string sector = path.substr(prefix.size(), dot - prefix.size());
    const std::string field = path.substr(dot + 1);
    if (dot <= prefix.size() ||
        (field != "min_complete_coverage" && field != "min_floor_coverage")) {
      return std::nullopt;
    }
    const bool complete = field == "min_complete_coverage";
    return Relaxable{[sector, complete](model::Requirements& r) -> double* {
                       for (model::SectorRequirement& s : r.sectors) {
                         if (s.name == sector)
                           return complete ? &s.min_complete_coverage : &s.min_floor_coverage;
                       }
                       return nullptr;
                     },
                     "share", false, 0, 1};
  }
  return std::nullopt;
}

[[noreturn]] void fail(const model::RelaxationStep& step, const std::string& problem,
                       const std::string& expected) {
  throw model::InputError(model::Diagnostic{step.where, "steps.relax",
                                            "'" + step.requirement + "' " + problem, expected});
}

const char* kRelaxable =
    "robot_speed.max_speed, robot_speed.max_travel_between_frames, "
    "object_dynamics.max_object_speed, object_dynamics.max_travel_between_frames, "
    "range.min_frequency, range.distance, smallest_obstacle.size, accuracy.max_noise, "
    "sectors.<name>.min_complete_coverage, sectors.<name>.min_floor_coverage, lighting";

}  // namespace

model::Requirements relax(const model::Requirements& requirements,
                          const model::RelaxationStep& step) {
  model::Requirements relaxed = requirements;
  if (step.requirement == "lighting") {
    if (!step.drop) fail(step, "needs `drop: <condition>`", "drop: dark, indoor or sunlight");
    const auto it = std::find(relaxed.lighting.begin(), relaxed.lighting.end(), *step.drop);
    if (it == relaxed.lighting.end()) {
      fail(step, "does not require " + to_string(*step.drop), "a condition the requirements list");
    }
    relaxed.lighting.erase(it);
    return relaxed;
  }
  const std::optional<Relaxable> target = relaxable(step.requirement);
  if (!target) fail(step, "is not a relaxable requirement", std::string("one of: ") + kRelaxable);
  if (!step.to) fail(step, "needs `to: <value>`", "the relaxed value in " + target->unit);
  double* value = target->value(relaxed);
  if (value == nullptr) {
    fail(step, "is not stated in " + requirements.file,
         "a requirement the requirements file states");
  }
  if (*step.to <= target->low || *step.to > target->high) {
    if (!(target->unit == "share" && *step.to == 0.0)) {
      fail(step, "cannot be " + model::format_number(*step.to),
           target->unit == "share" ? "a share in [0, 1]" : "a positive number in " + target->unit);
    }
  }
  const bool looser = target->looser_is_larger ? *step.to > *value : *step.to < *value;
  if (!looser) {
    fail(step,
         "would go from " + model::format_number(*value) + " to " + model::format_number(*step.to) +
             ", which tightens it",
         std::string("a value ") + (target->looser_is_larger ? "above " : "below ") +
             model::format_number(*value) + " " + target->unit);
  }
  *value = *step.to;
  return relaxed;
}

std::string describe(const model::Requirements& before, const model::RelaxationStep& step) {
  if (step.requirement == "lighting") return "lighting: drop " + to_string(*step.drop);
  model::Requirements copy = before;
  const std::optional<Relaxable> target = relaxable(step.requirement);
  const double* value = target ? target->value(copy) : nullptr;
  const std::string unit = target && target->unit != "share" ? " " + target->unit : "";
  return step.requirement + " " + (value ? model::format_number(*value) : "?") + " -> " +
         model::format_number(*step.to) + unit;
}

}  // namespace rigdesign::select
