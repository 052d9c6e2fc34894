#pragma once
/// Continuous refinement of a grid optimum's poses (issue 15). The search is proven optimal
/// over the pose ranges' grids; between grid values a pose may hold a wider margin. A
/// compass search moves each axis a chosen slot's range varies (inside the range's bounds,
/// never into the body), keeps a move only when it widens the rig's margins to the sector
/// thresholds (and to the robustness thresholds after each failure) compared smallest first
/// (leximin: the smallest never shrinks), and halves its steps when no move helps. Margins come
/// from rasters at the sectors' angles, as in the search; the refined rig replaces the grid one
/// only when the exact path confirms every sector (and every failure), so refinement never breaks a
/// requirement. Sensors, modes and cost never change.
#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "rigdesign/select/selection.hpp"

namespace rigdesign::select {

/// Raster margins of a rig whose mounts come from catalog options, one mount movable.
class RasterMargins {
 public:
  RasterMargins(const SelectionSpace& space, const SatisficingTargets& targets,
                const model::Rig& rig);
  ~RasterMargins();
  RasterMargins(const RasterMargins&) = delete;
  RasterMargins& operator=(const RasterMargins&) = delete;

  /// Every sector's smallest margin (and every robustness sector's after each failure to
  /// survive), smallest first, with the mount's pose replaced by `pose`.
  std::vector<double> margins_with(std::size_t mount, const model::Pose3& pose);
  /// Of the rig as it is.
  std::vector<double> margins();
  /// Each target sector's margin (no failure), in the targets' order, with the mount moved.
  std::vector<double> sector_margins_with(std::size_t mount, const model::Pose3& pose);
  /// Moves the mount for good.
  void move(std::size_t mount, const model::Pose3& pose);
  /// Whether a sensor origin at `pose` would sit inside the body.
  bool inside_body(const model::Pose3& pose) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// Refines the poses of `selection` (found by select_cheapest for `targets`).
/// `progress` hears the compass search ("pose refinement", rigs of at most
/// kMaxRefinementRigs) and the refined rig's exact verification.
PoseRefinement refine_poses(const SelectionSpace& space, const Selection& selection,
                            const SatisficingTargets& targets, const ProgressSink& progress = {});

/// The compass search stops after this many rigs at the latest.
inline constexpr int kMaxRefinementRigs = 400;

/// One sample of a sweep: the axis value [SI], the rig's smallest margin and each target
/// sector's margin (in the targets' order) [share].
struct MarginSample {
  double at = 0.0;
  double smallest = 0.0;
  std::vector<double> sectors;
};

/// The margins of `rig` as axis `range.axis` of mount `mount` sweeps the range's [low, high]
/// in `samples` even steps, the mount's other axes at `values` and the other mounts fixed
/// (values inside the body skipped). For the margin-against-pitch plot.
std::vector<MarginSample> margin_sweep(const SelectionSpace& space,
                                       const SatisficingTargets& targets, const model::Rig& rig,
                                       std::size_t mount, const std::array<double, 6>& values,
                                       const model::PoseAxisRange& range, int samples);

/// The pose of a pose-range slot with its axis values replaced by `values` (SI).
model::Pose3 pose_from_values(const std::array<double, 6>& values);

}  // namespace rigdesign::select
