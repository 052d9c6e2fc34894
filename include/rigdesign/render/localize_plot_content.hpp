#pragma once
/// What a localisation plot shows, taken from the localize module's results: the logged path
/// with its values, walls, estimates with their twins, gas detections and artifacts.
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/localize/co2_log.hpp"
#include "rigdesign/localize/emitter_localizer.hpp"
#include "rigdesign/localize/gas_detection.hpp"
#include "rigdesign/localize/ground_truth.hpp"
#include "rigdesign/localize/log_generator.hpp"
#include "rigdesign/localize/rssi_log.hpp"
#include "rigdesign/render/localize_plot.hpp"

namespace rigdesign::render {

/// The robot's path coloured by RSSI.
LocalizePlot rssi_plot(const localize::RssiLog& log, std::string title);

/// The robot's path coloured by CO2.
LocalizePlot co2_plot(const localize::Co2Log& log, std::string title);

void add_walls(const std::vector<localize::WallSegment>& walls, LocalizePlot& plot);

/// Every hypothesis (the first as the estimate, the others as twins) with its covariance, and
/// the truth when known (once, however many estimates share it).
void add_estimate_markers(const localize::EmitterEstimate& estimate,
                          const std::optional<model::Vec3>& truth, LocalizePlot& plot);

/// Where each detection fired and where the lag correction puts it.
void add_detection_markers(const std::vector<localize::GasDetection>& detections,
                           LocalizePlot& plot);

/// The gas artifacts among `artifacts`.
void add_gas_artifact_markers(const std::vector<localize::Artifact>& artifacts, LocalizePlot& plot);

}  // namespace rigdesign::render
