#include "rigdesign/deploy/blind_memory.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::deploy {
namespace {

// Along-track position x of an obstacle at lateral offset `lateral` seen at azimuth `angle`
// (folded into [0, pi]: the rule is the same on both sides).
double along(double lateral, double angle) {
  return lateral / std::tan(std::clamp(angle, 1e-6, std::numbers::pi - 1e-6));
}

double folded(double theta) {
  const double a = model::wrap_angle(theta);
  return a > std::numbers::pi ? 2 * std::numbers::pi - a : a;
}

// Blind azimuths: where none of the floor is seen (a cable or a foot there is invisible); for
// a rig that sees no floor anywhere (level scan planes), where nothing of the section is seen.
std::vector<bool> blind_azimuths(const std::vector<metrics::AngleCoverage>& angles) {
  const bool sees_floor = std::any_of(
      angles.begin(), angles.end(), [](const metrics::AngleCoverage& a) { return a.floor > 0.0; });
  std::vector<bool> blind;
  for (const metrics::AngleCoverage& angle : angles)
    blind.push_back(sees_floor ? angle.floor <= 0.0 : angle.complete <= 0.0);
  return blind;
}

// What a grazing obstacle does on one side of the robot: kept while in the gap, seen before.
struct Pass {
  double keep = 0.0;   // [m]
  double seen = 0.0;   // [m]
  int last_seen = -1;  // index of the azimuth where it is seen last before the gap; -1: none
};

// The pass of an obstacle that enters the gap at angles[enter] (on the left when `left`) and
// leaves it at folded azimuth `a_leave` (pi: never, it is kept until the body has passed it).
Pass pass_from(const std::vector<metrics::AngleCoverage>& angles, const std::vector<bool>& blind,
               int enter, bool left, double a_leave, double step, double d) {
  const int n = static_cast<int>(angles.size());
  const double a_enter = folded(angles[enter].theta);
  const double lateral = angles[enter].r;
  const double x_enter = along(lateral, a_enter);
  const double x_leave =
      a_leave >= std::numbers::pi - 1.5 * step ? -lateral : along(lateral, a_leave);
  // The seen run before the gap, walking towards the front.
  int seen = 0;
  for (int j = 1; j < n; ++j) {
    const int index = ((enter + (left ? -j : j)) % n + n) % n;
    if (blind[index] || folded(angles[index].theta) > a_enter) break;
    ++seen;
  }
  const double a_seen = std::max(0.0, a_enter - seen * step);
  const double x_first =
      std::min(std::sqrt(std::max(0.0, d * d - lateral * lateral)), along(lateral, a_seen));
  const int last_seen = seen > 0 ? ((enter + (left ? -1 : 1)) % n + n) % n : -1;
  return {std::max(0.0, x_enter - x_leave), std::max(0.0, x_first - x_enter), last_seen};
}

// The Hit Layer's keep, in seconds: hit_max updates of the costmap.
int hit_max_of(double keep_distance, double min_speed, double update_rate) {
  return std::max(1,
                  static_cast<int>(std::ceil(2 * update_rate * keep_distance / min_speed - 1e-9)));
}

double persistence_of(double keep_distance, double min_speed, double update_rate) {
  return hit_max_of(keep_distance, min_speed, update_rate) / update_rate;
}

}  // namespace

BlindMemory blind_memory(const metrics::RigCoverage& coverage, double max_speed, double min_speed,
                         double update_rate) {
  BlindMemory memory;
  memory.max_speed = max_speed;
  memory.min_speed = min_speed;
  memory.update_rate = update_rate;
  const std::vector<metrics::AngleCoverage>& angles = coverage.angles;
  const int n = static_cast<int>(angles.size());
  const std::vector<bool> blind = blind_azimuths(angles);
  const bool all_blind = std::all_of(blind.begin(), blind.end(), [](bool b) { return b; });
  const bool none_blind = std::none_of(blind.begin(), blind.end(), [](bool b) { return b; });
  if (n == 0 || all_blind || none_blind) {
    memory.rule = none_blind ? "the rig sees something at every azimuth: paper 1's values"
                             : "the rig sees nothing at any azimuth: paper 1's values";
    return memory;
  }
  // Start the walk at a seen azimuth so that every gap is a whole run.
  int start = 0;
  while (blind[start]) ++start;
  const double step = 2 * std::numbers::pi / n;
  const auto pass = [&](int enter, bool left, double a_leave) {
    return pass_from(angles, blind, enter, left, a_leave, step, coverage.distance);
  };
  for (int k = 0; k < n;) {
    const int i = (start + k) % n;
    if (!blind[i]) {
      ++k;
      continue;
    }
    int length = 0;
    while (k + length < n && blind[(start + k + length) % n]) ++length;
    k += length;
    // On the left (azimuths in (0, pi)) a passed obstacle moves towards larger azimuths, on
    // the right towards smaller ones; a gap across pi (astern) is entered from both sides
    // and never left, a gap across 0 (ahead) is not passed driving forward.
    const double first = angles[i].theta;
    const double last = first + (length - 1) * step;
    const int last_index = (start + k - 1) % n;
    const bool across_back = first <= std::numbers::pi + 1e-9 && last >= std::numbers::pi - 1e-9;
    const bool across_front = last >= 2 * std::numbers::pi - 1e-9;
    std::vector<Pass> passes;
    if (across_back) {
      if (first < std::numbers::pi - 1e-9) passes.push_back(pass(i, true, std::numbers::pi));
      if (last > std::numbers::pi + 1e-9)
        passes.push_back(pass(last_index, false, std::numbers::pi));
    } else if (!across_front) {
      passes.push_back(last < std::numbers::pi ? pass(i, true, folded(last))
                                               : pass(last_index, false, folded(first)));
    }
    if (passes.empty()) continue;
    const Pass& longest = *std::max_element(
        passes.begin(), passes.end(), [](const Pass& a, const Pass& b) { return a.keep < b.keep; });
    // An obstacle already behind the body when it enters the gap needs no keeping.
    if (!(longest.keep > 0.0)) continue;
    BlindGap gap;
    gap.from = first;
    gap.to = last;
    gap.keep_distance = longest.keep;
    gap.seen_distance = longest.seen;
    gap.last_seen = longest.last_seen;
    gap.persistence = persistence_of(longest.keep, min_speed, update_rate);
    gap.reaches_back = across_back || (last < std::numbers::pi ? folded(last) : folded(first)) >=
                                          std::numbers::pi - 1.5 * step;
    memory.gaps.push_back(gap);
  }
  for (std::size_t g = 0; g < memory.gaps.size(); ++g) {
    if (memory.worst_gap < 0 ||
        memory.gaps[g].keep_distance > memory.gaps[memory.worst_gap].keep_distance) {
      memory.worst_gap = static_cast<int>(g);
    }
  }
  if (memory.worst_gap < 0) {
    memory.rule = "no blind gap is passed while driving forward: paper 1's values";
    return memory;
  }
  const BlindGap& worst = memory.gaps[memory.worst_gap];
  const double keep_updates = update_rate * worst.keep_distance / min_speed;
  const double seen_updates = update_rate * worst.seen_distance / max_speed;
  memory.hit.hit_max = hit_max_of(worst.keep_distance, min_speed, update_rate);
  memory.persistence = worst.persistence;
  memory.hit.hit = std::clamp(
      static_cast<int>(std::ceil(memory.hit.hit_max / std::max(seen_updates, 1.0) - 1e-9)), 1,
      memory.hit.hit_max);
  const auto number = [](double value) { return model::format_number(value, 3); };
  memory.rule = "largest blind gap " + number(model::rad_to_deg(worst.from)) + ".." +
                number(model::rad_to_deg(worst.to)) +
                " deg: an obstacle grazing the body is in it for " + number(worst.keep_distance) +
                " m of travel (" + number(keep_updates) + " updates at " + number(min_speed) +
                " m/s, " + number(update_rate) + " Hz) and seen for " +
                number(worst.seen_distance) + " m before it (" + number(seen_updates) +
                " updates at " + number(max_speed) + " m/s): hit_max = ceil(2 x " +
                number(keep_updates) + ") = " + std::to_string(memory.hit.hit_max) +
                ", hit = ceil(hit_max / " + number(std::max(seen_updates, 1.0)) +
                ") = " + std::to_string(memory.hit.hit) + "; observation_persistence = hit_max / " +
                number(update_rate) + " Hz = " + number(memory.persistence) + " s";
  return memory;
}

}  // namespace rigdesign::deploy
