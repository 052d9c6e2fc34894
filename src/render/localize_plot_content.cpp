#include "rigdesign/render/localize_plot_content.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rigdesign/model/format_number.hpp"

namespace rigdesign::render {

namespace {

// The path of a log's readings, coloured by what `value_of` reads from each.
template <typename Reading, typename ValueOf>
LocalizePlot path_plot(const std::vector<Reading>& readings, ValueOf value_of, std::string title,
                       std::string value_label) {
  LocalizePlot plot;
  plot.title = std::move(title);
  plot.value_label = std::move(value_label);
  for (const Reading& r : readings) {
    plot.path.push_back(r.position);
    plot.values.push_back(value_of(r));
  }
  return plot;
}

}  // namespace

LocalizePlot rssi_plot(const localize::RssiLog& log, std::string title) {
  return path_plot(
      log.readings,
      [](const localize::RssiReading& r) {
        return r.heard ? r.rssi_dbm : std::numeric_limits<double>::quiet_NaN();
      },
      std::move(title), "RSSI [dBm]");
}

LocalizePlot co2_plot(const localize::Co2Log& log, std::string title) {
  return path_plot(
      log.readings, [](const localize::Co2Reading& r) { return r.ppm; }, std::move(title),
      "CO2 [ppm]");
}

void add_walls(const std::vector<localize::WallSegment>& walls, LocalizePlot& plot) {
  for (const localize::WallSegment& wall : walls) plot.walls.emplace_back(wall.a, wall.b);
}

void add_estimate_markers(const localize::EmitterEstimate& estimate,
                          const std::optional<model::Vec3>& truth, LocalizePlot& plot) {
  for (std::size_t i = 0; i < estimate.hypotheses.size(); ++i) {
    const localize::Hypothesis& h = estimate.hypotheses[i];
    plot.markers.push_back(
        {h.position, h.covariance.topLeftCorner<2, 2>(),
         to_string(estimate.method) + (i == 0 ? "" : " hypothesis " + std::to_string(i + 1)) +
             (estimate.hypotheses.size() > 1
                  ? " (p " + model::format_number(std::round(100 * h.probability) / 100) + ")"
                  : std::string()),
         i == 0 ? PlotMarkerKind::estimate : PlotMarkerKind::alternative});
  }
  // The range fit's credible region (one per plot: the first nls estimate drawn).
  if (estimate.method == localize::LocalizeMethod::nls && estimate.region &&
      plot.region_cells.empty()) {
    const localize::PositionPosterior& region = *estimate.region;
    for (int r = 0; r < region.rows; ++r)
      for (int c = 0; c < region.columns; ++c)
        if (region.log_density[static_cast<std::size_t>(r * region.columns + c)] >=
            region.threshold)
          plot.region_cells.push_back(region.centre(c, r));
    plot.region_cell = region.cell;
    plot.region_label = to_string(estimate.method) + " " +
                        model::format_number(100 * region.credible_mass) + " % region";
  }
  const bool drawn =
      std::any_of(plot.markers.begin(), plot.markers.end(), [&](const PlotMarker& m) {
        return m.kind == PlotMarkerKind::truth && truth && m.position == *truth;
      });
  if (truth && !drawn)
    plot.markers.push_back(
        {*truth, Eigen::Matrix2d::Zero(), estimate.bssid, PlotMarkerKind::truth});
}

void add_detection_markers(const std::vector<localize::GasDetection>& detections,
                           LocalizePlot& plot) {
  for (const localize::GasDetection& d : detections) {
    plot.markers.push_back({d.position, Eigen::Matrix2d::Zero(), "", PlotMarkerKind::detection});
    plot.markers.push_back(
        {d.lag_corrected, Eigen::Matrix2d::Zero(), "", PlotMarkerKind::lag_corrected});
  }
}

void add_gas_artifact_markers(const std::vector<localize::Artifact>& artifacts,
                              LocalizePlot& plot) {
  for (const localize::Artifact& a : artifacts) {
    if (a.type == "gas")
      plot.markers.push_back({a.position, Eigen::Matrix2d::Zero(), "gas " + std::to_string(a.id),
                              PlotMarkerKind::artifact});
  }
}

}  // namespace rigdesign::render
