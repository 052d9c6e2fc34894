#pragma once
/// Paper 3's occupancy evaluation (DESIGN.md section 7): a predicted set of occupied voxels
/// (or 2D cells) against the ground truth, P = TP / (TP + FP), R = TP / (TP + FN),
/// F_beta = (1 + beta^2) P R / (beta^2 P + R); plus the whole-grid measures of issue 6:
/// ghost area, misses split by cause, and per-cell delays to mark and to clear.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "rigdesign/costmap/rolling_voxel_grid.hpp"

namespace rigdesign::occupancy {

struct ConfusionCounts {
  std::size_t true_positives = 0;
  std::size_t false_positives = 0;
  std::size_t false_negatives = 0;

  /// TP / (TP + FP); NaN when nothing was predicted (undefined, skipped by mean_scores).
  double precision() const;
  /// TP / (TP + FN); NaN when the truth is empty.
  double recall() const;
  /// (1 + b^2) P R / (b^2 P + R); NaN when P or R is, 0 when both are 0.
  double f_beta(double beta) const;
};

struct Scores {
  double precision = 0.0;
  double recall = 0.0;
  double f1 = 0.0;
  double f2 = 0.0;
  double f3 = 0.0;
};

Scores scores_of(const ConfusionCounts& counts);
/// The mean of each score over frames, each skipping the frames where it is NaN (NaN when all
/// are); paper 3 reports per-frame scores and their mean.
Scores mean_scores(std::span<const Scores> frames);

/// Counts on voxel sets (duplicates ignored; any order).
ConfusionCounts compare_voxel_sets(std::vector<costmap::VoxelKey> predicted,
                                   std::vector<costmap::VoxelKey> truth);
/// Counts on two masks of the same cells (non-zero = occupied).
ConfusionCounts compare_masks(std::span<const std::uint8_t> predicted,
                              std::span<const std::uint8_t> truth);

/// The false negatives split by cause: truth voxels no sensor saw this frame (no point fell
/// in them) versus voxels seen but not kept in the grid.
struct MissCauses {
  std::size_t never_seen = 0;
  std::size_t seen_not_kept = 0;
};
MissCauses split_misses(std::vector<costmap::VoxelKey> predicted,
                        std::vector<costmap::VoxelKey> truth, std::vector<costmap::VoxelKey> seen);

/// Area [m^2] of cells predicted occupied where the truth is free ("ghosts"), for masks of
/// the same cells of side `resolution` [m].
double ghost_area(std::span<const std::uint8_t> predicted, std::span<const std::uint8_t> truth,
                  double resolution);

/// Per-cell delays between the truth changing and the grid following it, over a sequence of
/// frames on the same world cells. Time to mark: from a cell's truth turning occupied to the
/// grid first showing it occupied; time to clear: from its truth turning free to the grid
/// first showing it free. A change the truth reverts before the grid follows counts as
/// missed (and leaves nothing pending). Cells already agreeing when the truth changes record
/// a delay of 0.
class ChangeDelays {
 public:
  explicit ChangeDelays(std::size_t cells);
  /// One frame at `time` [s] (increasing); masks as in compare_masks. The first frame only
  /// sets the starting state.
  void record(double time, std::span<const std::uint8_t> truth,
              std::span<const std::uint8_t> predicted);

  const std::vector<double>& mark_delays() const { return mark_delays_; }    ///< [s]
  const std::vector<double>& clear_delays() const { return clear_delays_; }  ///< [s]
  std::size_t missed_marks() const { return missed_marks_; }
  std::size_t missed_clears() const { return missed_clears_; }
  /// Changes the grid has not followed yet (at the last frame).
  std::size_t pending() const;

 private:
  std::vector<std::uint8_t> truth_;
  std::vector<double> since_;  // NaN: nothing pending; else when the truth last changed
  std::vector<double> mark_delays_;
  std::vector<double> clear_delays_;
  std::size_t missed_marks_ = 0;
  std::size_t missed_clears_ = 0;
  bool started_ = false;
};

}  // namespace rigdesign::occupancy
