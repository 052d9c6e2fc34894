#include "rigdesign/occupancy/occupancy_scores.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rigdesign::occupancy {
namespace {

constexpr double kUndefined = std::numeric_limits<double>::quiet_NaN();

double ratio(std::size_t numerator, std::size_t denominator) {
  return denominator == 0 ? kUndefined
                          : static_cast<double>(numerator) / static_cast<double>(denominator);
}

void require_same_size(std::size_t a, std::size_t b, const char* what) {
  if (a != b) throw std::invalid_argument(std::string(what) + ": the masks differ in size");
}

double mean_skipping_nan(std::span<const Scores> frames, double Scores::*score) {
  double sum = 0.0;
  std::size_t count = 0;
  for (const Scores& frame : frames) {
    if (std::isnan(frame.*score)) continue;
    sum += frame.*score;
    ++count;
  }
  return count == 0 ? kUndefined : sum / static_cast<double>(count);
}

}  // namespace

double ConfusionCounts::precision() const {
  return ratio(true_positives, true_positives + false_positives);
}

double ConfusionCounts::recall() const {
  return ratio(true_positives, true_positives + false_negatives);
}

double ConfusionCounts::f_beta(double beta) const {
  const double p = precision();
  const double r = recall();
  if (std::isnan(p) || std::isnan(r)) return kUndefined;
  const double b2 = beta * beta;
  const double denominator = b2 * p + r;
  return denominator == 0.0 ? 0.0 : (1 + b2) * p * r / denominator;
}

Scores scores_of(const ConfusionCounts& counts) {
  return {counts.precision(), counts.recall(), counts.f_beta(1), counts.f_beta(2),
          counts.f_beta(3)};
}

Scores mean_scores(std::span<const Scores> frames) {
  return {mean_skipping_nan(frames, &Scores::precision), mean_skipping_nan(frames, &Scores::recall),
          mean_skipping_nan(frames, &Scores::f1), mean_skipping_nan(frames, &Scores::f2),
          mean_skipping_nan(frames, &Scores::f3)};
}

ConfusionCounts compare_voxel_sets(std::vector<costmap::VoxelKey> predicted,
                                   std::vector<costmap::VoxelKey> truth) {
  costmap::sort_unique(predicted);
  costmap::sort_unique(truth);
  std::vector<costmap::VoxelKey> common;
  std::set_intersection(predicted.begin(), predicted.end(), truth.begin(), truth.end(),
                        std::back_inserter(common));
  return {common.size(), predicted.size() - common.size(), truth.size() - common.size()};
}

ConfusionCounts compare_masks(std::span<const std::uint8_t> predicted,
                              std::span<const std::uint8_t> truth) {
  require_same_size(predicted.size(), truth.size(), "compare_masks");
  ConfusionCounts counts;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const bool p = predicted[i] != 0;
    const bool t = truth[i] != 0;
    counts.true_positives += p && t;
    counts.false_positives += p && !t;
    counts.false_negatives += !p && t;
  }
  return counts;
}

MissCauses split_misses(std::vector<costmap::VoxelKey> predicted,
                        std::vector<costmap::VoxelKey> truth, std::vector<costmap::VoxelKey> seen) {
  costmap::sort_unique(predicted);
  costmap::sort_unique(truth);
  costmap::sort_unique(seen);
  std::vector<costmap::VoxelKey> missed;
  std::set_difference(truth.begin(), truth.end(), predicted.begin(), predicted.end(),
                      std::back_inserter(missed));
  std::vector<costmap::VoxelKey> missed_seen;
  std::set_intersection(missed.begin(), missed.end(), seen.begin(), seen.end(),
                        std::back_inserter(missed_seen));
  return {missed.size() - missed_seen.size(), missed_seen.size()};
}

double ghost_area(std::span<const std::uint8_t> predicted, std::span<const std::uint8_t> truth,
                  double resolution) {
  return static_cast<double>(compare_masks(predicted, truth).false_positives) * resolution *
         resolution;
}

ChangeDelays::ChangeDelays(std::size_t cells) : truth_(cells, 0), since_(cells, kUndefined) {}

void ChangeDelays::record(double time, std::span<const std::uint8_t> truth,
                          std::span<const std::uint8_t> predicted) {
  require_same_size(truth.size(), truth_.size(), "ChangeDelays::record");
  require_same_size(predicted.size(), truth_.size(), "ChangeDelays::record");
  for (std::size_t i = 0; i < truth_.size(); ++i) {
    const std::uint8_t now = truth[i] != 0;
    const bool agrees = (predicted[i] != 0) == (now != 0);
    const bool changed = started_ && now != truth_[i];
    truth_[i] = now;
    if (changed && !std::isnan(since_[i])) {
      // Reverted before the grid followed: the grid still shows the state the truth is back to.
      ++(now ? missed_clears_ : missed_marks_);
      since_[i] = kUndefined;
      continue;
    }
    if (changed) since_[i] = time;
    if (!std::isnan(since_[i]) && agrees) {
      (now ? mark_delays_ : clear_delays_).push_back(time - since_[i]);
      since_[i] = kUndefined;
    }
  }
  started_ = true;
}

std::size_t ChangeDelays::pending() const {
  return static_cast<std::size_t>(
      std::count_if(since_.begin(), since_.end(), [](double t) { return !std::isnan(t); }));
}

}  // namespace rigdesign::occupancy
