#pragma once
/// Top view of a localisation run (PNG or SVG by extension): the robot's path coloured by the
/// measured value (RSSI or CO2; scans that heard nothing as grey rings), walls, the range fit's
/// 95 % region, estimates with their 2-sigma ellipses, other hypotheses, the truth, gas
/// detections and artifacts. Axes in metres, equal scale.
#include <string>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::render {

enum class PlotMarkerKind { estimate, alternative, truth, detection, lag_corrected, artifact };

struct PlotMarker {
  model::Vec3 position = model::Vec3::Zero();
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();  ///< [m^2]; drawn as a 2-sigma ellipse
  std::string label;
  PlotMarkerKind kind = PlotMarkerKind::estimate;
};

struct LocalizePlot {
  std::string title;
  std::vector<model::Vec3> path;  ///< reading positions [m]
  std::vector<double> values;     ///< one per path point (may be empty)
  std::string value_label;        ///< e.g. "RSSI [dBm]"
  std::vector<std::pair<model::Vec2, model::Vec2>> walls;
  std::vector<PlotMarker> markers;
  /// Centres of the cells of a stated credible region (the range fit's 95 % region), each
  /// `region_cell` metres wide; drawn as a shaded area under the markers.
  std::vector<model::Vec2> region_cells;
  double region_cell = 0.0;
  std::string region_label;  ///< its legend entry, e.g. "nls 95 % region"
};

void plot_localization(const LocalizePlot& plot, const std::string& path, int width = 1000,
                       int height = 820);

}  // namespace rigdesign::render
