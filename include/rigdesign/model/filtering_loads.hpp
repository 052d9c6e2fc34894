#pragma once
/// Measured filtering load per sensor (paper 1, eq. 5's U_f), as `rigdesign filter --write-loads`
/// records it and catalogs (`filtering_loads:`) and `rigdesign metrics --filtering-loads` read it.
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/model/source_location.hpp"

namespace rigdesign::model {

struct FilteringLoad {
  std::string sensor_id;
  std::string mode_id;                    ///< the mode it was measured in
  double seconds_per_point = 0.0;         ///< [core-s] per delivered point: what U_f scales
  double points_per_frame = 0.0;          ///< mean delivered points per simulated frame
  double median_seconds_per_frame = 0.0;  ///< [s], single thread
  SourceLocation where;
};

struct FilteringLoads {
  std::string machine;   ///< what one core-equivalent means
  std::string pipeline;  ///< the pipeline that was timed
  std::string scene;     ///< where the frames came from
  int frames = 0;        ///< frames per sensor
  std::vector<FilteringLoad> sensors;
  std::string file;

  /// The measured load of `sensor_id`, if it was measured.
  const FilteringLoad* find(const std::string& sensor_id) const;
  /// Adds a measurement. Mounts of one sensor (three pico flexx, say) share its entry: the
  /// slower per point is kept, so a catalog never underprices the sensor.
  void record(const FilteringLoad& load);
};

}  // namespace rigdesign::model
