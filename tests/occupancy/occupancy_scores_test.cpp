#include "rigdesign/occupancy/occupancy_scores.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

using namespace rigdesign;

namespace {

const costmap::VoxelKey A{0, 0, 0}, B{1, 0, 0}, C{0, 1, 0}, D{0, 0, 1}, E{5, 5, 5}, F{-1, 2, 3},
    G{9, 9, 9};

}  // namespace

TEST_CASE("precision, recall and F-beta on a hand-counted case", "[costmap]") {
  // Predicted {A, B, C, D} (B listed twice), truth {B, C, E}: TP 2, FP 2 (A, D), FN 1 (E).
  const occupancy::ConfusionCounts counts =
      occupancy::compare_voxel_sets({A, B, C, D, B}, {E, C, B});
  CHECK(counts.true_positives == 2);
  CHECK(counts.false_positives == 2);
  CHECK(counts.false_negatives == 1);
  const occupancy::Scores s = occupancy::scores_of(counts);
  CHECK(s.precision == Approx(0.5));
  CHECK(s.recall == Approx(2.0 / 3.0));
  CHECK(s.f1 == Approx(4.0 / 7.0));    // 2 (1/3) / (7/6)
  CHECK(s.f2 == Approx(5.0 / 8.0));    // 5 (1/3) / (2 + 2/3)
  CHECK(s.f3 == Approx(20.0 / 31.0));  // 10 (1/3) / (4.5 + 2/3)
  // Paper 3's OctoMap row: P 0.650 and R 0.477 give F1 0.550.
  const double p = 0.650, r = 0.477;
  CHECK(2 * p * r / (p + r) == Approx(0.550).epsilon(1e-3));
}

TEST_CASE("undefined scores are NaN and the mean skips them", "[costmap]") {
  const occupancy::Scores empty = occupancy::scores_of(occupancy::compare_voxel_sets({}, {}));
  CHECK(std::isnan(empty.precision));
  CHECK(std::isnan(empty.f1));
  const occupancy::Scores none_right =
      occupancy::scores_of(occupancy::compare_voxel_sets({A}, {B}));
  CHECK(none_right.precision == 0.0);
  CHECK(none_right.f1 == 0.0);
  const occupancy::Scores perfect = occupancy::scores_of(occupancy::compare_voxel_sets({A}, {A}));
  const std::vector<occupancy::Scores> frames{empty, none_right, perfect};
  const occupancy::Scores mean = occupancy::mean_scores(frames);
  CHECK(mean.precision == Approx(0.5));
  CHECK(mean.f3 == Approx(0.5));
}

TEST_CASE("masks, ghost area and misses by cause", "[costmap]") {
  const std::vector<std::uint8_t> predicted{1, 1, 0, 1};
  const std::vector<std::uint8_t> truth{0, 1, 1, 0};
  const occupancy::ConfusionCounts counts = occupancy::compare_masks(predicted, truth);
  CHECK(counts.true_positives == 1);
  CHECK(counts.false_positives == 2);
  CHECK(counts.false_negatives == 1);
  CHECK(occupancy::ghost_area(predicted, truth, 0.1) == Approx(0.02));  // 2 cells of 0.01 m^2
  // Truth {B, C, E, F}, kept {B}; the sensors saw C, E and G: C and E were seen but not kept,
  // F never seen.
  const occupancy::MissCauses causes = occupancy::split_misses({B}, {B, C, E, F}, {C, E, G});
  CHECK(causes.seen_not_kept == 2);
  CHECK(causes.never_seen == 1);
}

TEST_CASE("time to mark and time to clear, per cell", "[costmap]") {
  occupancy::ChangeDelays delays(1);
  auto frame = [&](double t, int truth, int predicted) {
    const std::vector<std::uint8_t> tr{static_cast<std::uint8_t>(truth)};
    const std::vector<std::uint8_t> pr{static_cast<std::uint8_t>(predicted)};
    delays.record(t, tr, pr);
  };
  frame(0.0, 0, 0);  // start
  frame(1.0, 1, 0);  // the object arrives
  frame(1.5, 1, 0);
  frame(2.0, 1, 1);  // marked after 1 s
  frame(3.0, 0, 1);  // the object leaves
  frame(4.5, 0, 0);  // cleared after 1.5 s
  frame(5.0, 1, 0);  // arrives again ...
  frame(6.0, 0, 0);  // ... and leaves before the grid marked it: a missed mark
  frame(7.0, 1, 1);  // arrives and is marked in the same frame: 0 s
  frame(8.0, 0, 1);  // leaves; still shown at the end
  CHECK(delays.mark_delays() == std::vector<double>{1.0, 0.0});
  CHECK(delays.clear_delays() == std::vector<double>{1.5});
  CHECK(delays.missed_marks() == 1);
  CHECK(delays.missed_clears() == 0);
  CHECK(delays.pending() == 1);
}
