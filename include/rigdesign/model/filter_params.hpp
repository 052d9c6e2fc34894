#pragma once
/// Parameters of the point-cloud filter stages, with the papers' defaults (DESIGN.md
/// section 6). Plain data: io loads them from YAML, filters run them.
///
/// The stage registry, in the style of PDAL's named stages: a stage is its params struct (with
/// its registered name, kName) in StageParams, one `run` overload in filters/pipeline.cpp and
/// one reader in io/config/pipeline_loader.cpp. Every list of names is derived from
/// StageParams, and a stage without its run function or reader fails to compile.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace rigdesign::model {

struct VoxelGridParams {
  static constexpr std::string_view kName = "voxel_grid";  ///< its name in pipelines
  double leaf = 0.03;  ///< [m] voxel edge (paper 1: V1 = 3 cm); > 0
  /// [m] voxel boundaries lie at grid_offset + k * leaf on each axis. 0 is PCL's alignment,
  /// which puts the floor plane z = 0 exactly on a boundary, so sensor noise splits floor
  /// points between two voxel layers (about 16 % more voxels than a half-leaf offset gives).
  Eigen::Vector3d grid_offset = Eigen::Vector3d::Zero();
};

struct PassThroughParams {
  static constexpr std::string_view kName = "pass_through";  ///< its name in pipelines
  int axis = 2;                                              ///< 0 = x, 1 = y, 2 = z
  double min = -0.10;                                        ///< [m] A
  double max = 0.10;                                         ///< [m] B
  bool negative = false;                                     ///< keep what is outside instead
};

struct StatisticalOutlierParams {
  static constexpr std::string_view kName = "statistical_outlier";  ///< its name in pipelines
  int neighbours = 10;                                              ///< N; > 0
  double std_multiplier = 1.0;                                      ///< M
  /// [m] grid cell of the neighbour search; 0 picks one from the cloud (about N points per
  /// occupied cell). Only speed depends on it, never the result.
  double cell = 0.0;
  /// Threads for the neighbour queries (1 to kMaxFilterThreads); the result is the same for
  /// any count. Each thread takes at least kMinPointsPerFilterThread points (below that, a
  /// thread's start costs more than its share of the queries saves), and no more threads
  /// start than cores are idle at the time (a busy core only time-slices them).
  int threads = 1;
};

inline constexpr int kMaxFilterThreads = 64;
inline constexpr std::size_t kMinPointsPerFilterThread = 8000;

struct RansacPlaneParams {
  int iterations = 100;     ///< I: the most hypotheses tried
  double threshold = 0.03;  ///< T [m]: inlier distance
  std::uint64_t seed = 1;
  /// Stop early once k = log(1 - confidence) / log(1 - w^3) hypotheses were tried, w the best
  /// inlier share so far: the chance that an all-inlier sample was never drawn is below
  /// 1 - confidence (PCL's RandomSampleConsensus, probability 0.99). 1 tries all `iterations`.
  double confidence = 0.99;
  /// Only planes whose normal is within this angle of +z count [rad]; unset: any plane.
  std::optional<double> max_tilt;
};

/// Floor removal 1: a pass-through slice around the floor, a RANSAC plane on the slice,
/// its inliers removed from the cloud.
struct FloorRemoval1Params {
  static constexpr std::string_view kName = "floor_removal_1";  ///< its name in pipelines
  PassThroughParams slice;                                      ///< z in [-10, 10] cm
  RansacPlaneParams ransac;
};

/// Floor removal 2, paper 1's "enhanced" floor removal 1: the same pass-through slice where
/// the floor is searched, a copy of the slice voxelised at V2 = 30 cm on which RANSAC finds
/// the plane, then every point of the slice within T of that plane removed. Nothing outside
/// the slice is ever removed (a table top, a bed or a loading dock is not the floor). Inside
/// the slice the plane must also be near-horizontal: RANSAC ignores hypotheses tilted more
/// than `ransac.max_tilt` (15 degrees by default), a guard against a ramp or a low box side.
struct FloorRemoval2Params {
  static constexpr std::string_view kName = "floor_removal_2";  ///< its name in pipelines
  PassThroughParams slice;                                      ///< z in [-10, 10] cm
  double coarse_leaf = 0.30;                                    ///< V2 [m]; > 0
  /// All I hypotheses (confidence 1): the 30 cm copy of the slice holds a few hundred points,
  /// so the early stop would save little and the plane it keeps could differ more from PCL's.
  RansacPlaneParams ransac{100, 0.03, 1, 1.0, 0.2617993877991494};
};

/// Paper 2's negative obstacles: a point below `below` (a hole or a step down) is mirrored
/// to (x, y, -z), and a virtual point is added `virtual_height` above the floor where the ray
/// from the sensor origin O to the point crosses the floor:
/// P'' = (o_x + (x - o_x) s, o_y + (y - o_y) s, virtual_height), s = o_z / (o_z - z).
struct NegativeObstacleParams {
  static constexpr std::string_view kName = "negative_obstacles";  ///< its name in pipelines
  double below = -0.02;                                            ///< [m]
  double virtual_height = 0.10;                                    ///< [m]
};

/// A RANSAC plane whose inliers are removed (the dominant plane, whatever its tilt).
struct RemovePlaneParams {
  static constexpr std::string_view kName = "ransac_plane";  ///< its name in pipelines
  RansacPlaneParams ransac;
};

/// Paper 2's throttle (section 3.2: lidar data to 5 Hz, Kinect data to 2 Hz before
/// filtering): whole frames are kept at `rate_hz` and the others dropped, as a stream. The
/// frame at or after each multiple of 1 / rate_hz since the first kept frame is kept, so the
/// kept rate is min(sensor rate, rate_hz) in the long run, as a mount's throttle_hz counts it
/// (a 30 Hz Kinect at 2 Hz: every 15th frame). A lone cloud (run_pipeline) is the first frame
/// of its stream and always kept; filters::PipelineStream runs a stream.
struct ThrottleParams {
  static constexpr std::string_view kName = "throttle";  ///< its name in pipelines
  double rate_hz = 2.0;  ///< [Hz] paper 2: 2 for the Kinect (5 for the lidar); > 0
};

/// Paper 2's outlier removal (section 3.2): every point with fewer than `min_neighbours`
/// other points within `radius` removed. PCL's RadiusOutlierRemoval with
/// setMinNeighborsInRadius(min_neighbours): a neighbour at exactly `radius` counts. Paper 2
/// gives no values; these keep a surface point of a Kinect v1 at 4 m (about 7 mm spacing) or
/// of a scan line at 0.5 degrees and 3 m (26 mm) while removing isolated returns.
struct RadiusOutlierParams {
  static constexpr std::string_view kName = "radius_outlier";  ///< its name in pipelines
  double radius = 0.05;                                        ///< [m]; > 0
  int min_neighbours = 2;                                      ///< other points; > 0
};

using StageParams = std::variant<VoxelGridParams, StatisticalOutlierParams, PassThroughParams,
                                 RemovePlaneParams, FloorRemoval1Params, FloorRemoval2Params,
                                 NegativeObstacleParams, ThrottleParams, RadiusOutlierParams>;

struct Pipeline {
  std::string name;
  std::vector<StageParams> stages;
};

namespace detail {
template <typename Stages>
struct StageNameList;
template <typename... Stages>
struct StageNameList<std::variant<Stages...>> {
  static constexpr std::array<std::string_view, sizeof...(Stages)> names{Stages::kName...};
};
constexpr bool all_distinct(std::span<const std::string_view> names) {
  for (std::size_t i = 0; i < names.size(); ++i)
    for (std::size_t j = i + 1; j < names.size(); ++j)
      if (names[i] == names[j]) return false;
  return true;
}
}  // namespace detail

/// Registered stage names, in StageParams' order.
inline constexpr auto kStageNames = detail::StageNameList<StageParams>::names;
static_assert(detail::all_distinct(kStageNames), "two stages registered under one name");

/// kStageNames as strings, for messages: "voxel_grid", "statistical_outlier", "pass_through",
/// "ransac_plane", "floor_removal_1", "floor_removal_2", "negative_obstacles", "throttle",
/// "radius_outlier".
const std::vector<std::string>& stage_names();
std::string stage_name(const StageParams& params);

}  // namespace rigdesign::model
