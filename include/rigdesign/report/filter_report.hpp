#pragma once
// `rigdesign filter`'s two reports as data, built once by the command: per cloud file the
// pipeline's stages with their timing (and, with --mount, the filtering load U_f), or per mount
// of a rig in a synthetic scene its measured load (paper 1, eq. 5). report/filter_text and
// report/filter_json render them.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/filters/pipeline_timing.hpp"

namespace rigdesign::report {

/// The filtering load of the mount that recorded a cloud, at its mode's frame rate.
struct CloudLoad {
  std::string mount_id;
  double frequency = 0.0;  ///< [Hz]
  filters::FilteringLoadRate rate;
};

struct FilterCloudReport {
  std::string file;
  std::string format;  ///< as io::CloudReadReport names it
  std::size_t points = 0;
  std::size_t dropped_non_finite = 0;
  std::vector<std::string> ignored_fields;
  std::vector<filters::StageTiming> stages;
  std::size_t points_out = 0;
  filters::TimeSpread total;  ///< [s] per run, the stages' times added
  std::optional<CloudLoad> load;
  std::string output;  ///< the filtered cloud written, or empty
};

struct FilterCloudsReport {
  std::string pipeline;
  int runs = 0;
  std::vector<FilterCloudReport> clouds;
  double peak_memory_mib = 0.0;
};

struct FilterMountReport {
  std::string mount_id;
  double frequency = 0.0;  ///< [Hz]
  std::size_t points_per_frame = 0;
  std::size_t kept_per_frame = 0;
  filters::TimeSpread seconds_per_frame;
  filters::FilteringLoadRate load;
};

struct FilterSceneReport {
  std::string rig_name;
  std::string scene;
  std::string pipeline;
  int frames = 0;
  std::vector<FilterMountReport> mounts;
  double total_load_cores = 0.0;
  std::string loads_file;  ///< where --write-loads wrote the loads, or empty
};

}  // namespace rigdesign::report
