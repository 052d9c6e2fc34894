#include "rigdesign/localize/gas_detection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rigdesign/model/statistics.hpp"

namespace rigdesign::localize {
namespace {

constexpr double kMadToSigma = 1.4826;  // MAD of a normal distribution times this is sigma

double horizontal(const model::Vec3& a, const model::Vec3& b) {
  return std::hypot(a.x() - b.x(), a.y() - b.y());
}

double time_of(const Co2Log& log, std::size_t i, const GasDetectionParams& params) {
  return log.timed ? log.readings[i].t : static_cast<double>(i) * params.sample_period;
}

// Running baseline from the readings before i: median + k sigma (sigma from the MAD), but at
// least min_rise above the median, so a flat trace (MAD 0) does not fire on 1 ppm.
double relative_threshold(const Co2Log& log, std::size_t i, const GasDetectionParams& params) {
  const std::size_t window = static_cast<std::size_t>(params.baseline_window);
  const std::size_t begin = i > window ? i - window : 0;
  if (i - begin < static_cast<std::size_t>(params.min_baseline))
    return std::numeric_limits<double>::infinity();
  std::vector<double> values;
  for (std::size_t k = begin; k < i; ++k) values.push_back(log.readings[k].ppm);
  const double median = model::median(values);
  for (double& v : values) v = std::abs(v - median);
  const double sigma = kMadToSigma * model::median(values);
  return median + std::max(params.mad_factor * sigma, params.min_rise_ppm);
}

// The position on the path `lag` seconds before reading i, interpolated between readings.
model::Vec3 position_before(const Co2Log& log, std::size_t i, double lag,
                            const GasDetectionParams& params) {
  const double target = time_of(log, i, params) - lag;
  std::size_t k = i;
  while (k > 0 && time_of(log, k - 1, params) > target) --k;
  if (k == 0) return log.readings.front().position;
  const double t0 = time_of(log, k - 1, params), t1 = time_of(log, k, params);
  const double share = t1 > t0 ? std::clamp((target - t0) / (t1 - t0), 0.0, 1.0) : 0.0;
  return log.readings[k - 1].position +
         share * (log.readings[k].position - log.readings[k - 1].position);
}

}  // namespace

double detection_lag(const Co2Log& log, const GasDetectionParams& params) {
  double period = params.sample_period;
  if (log.timed && log.readings.size() > 1) {
    std::vector<double> steps;
    for (std::size_t i = 1; i < log.readings.size(); ++i)
      steps.push_back(log.readings[i].t - log.readings[i - 1].t);
    period = model::median(steps);
  }
  return params.time_constant + 0.5 * (params.moving_average - 1) * period;
}

std::vector<GasDetection> detect_gas(const Co2Log& log, GasThreshold threshold,
                                     const GasDetectionParams& params) {
  std::vector<GasDetection> detections;
  const std::size_t n = log.readings.size();
  const std::size_t width = static_cast<std::size_t>(std::max(1, params.moving_average));
  const double lag = detection_lag(log, params);
  bool active = false;
  GasDetection current;
  const auto finish = [&] {
    current.lag_corrected = position_before(log, current.index, lag, params);
    detections.push_back(current);
    active = false;
  };
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sum += log.readings[i].ppm;
    if (i >= width) sum -= log.readings[i - width].ppm;
    if (i + 1 < width) continue;  // the moving average needs its window full
    // A single reading is taken as logged (the running sum could differ from it by rounding).
    const double average = width == 1 ? log.readings[i].ppm : sum / static_cast<double>(width);
    const model::Vec3& here = log.readings[i].position;
    if (active) {
      if (horizontal(here, log.readings[current.trigger_index].position) <= params.spacing) {
        if (params.refine_strongest && average > current.ppm) {
          current.index = i;
          current.position = here;
          current.ppm = average;
        }
        continue;
      }
      finish();
    }
    const double limit = threshold == GasThreshold::fixed ? params.fixed_threshold_ppm
                                                          : relative_threshold(log, i, params);
    if (!(average > limit)) continue;  // "over" the threshold, as the thesis says
    const bool near_earlier = std::any_of(
        detections.begin(), detections.end(),
        [&](const GasDetection& d) { return horizontal(here, d.position) < params.spacing; });
    if (near_earlier) continue;
    active = true;
    current = GasDetection{i, i, here, here, average, limit};
  }
  if (active) finish();
  return detections;
}

GasScore score_gas(const Co2Log& log, const std::vector<GasDetection>& detections,
                   const std::vector<Artifact>& artifacts, bool lag_corrected, double radius) {
  GasScore score;
  for (const Artifact& artifact : artifacts) {
    if (artifact.type != "gas") continue;
    GasArtifactResult result;
    result.artifact = artifact;
    result.path_distance = std::numeric_limits<double>::infinity();
    for (const Co2Reading& reading : log.readings) {
      result.path_distance =
          std::min(result.path_distance, horizontal(reading.position, artifact.position));
    }
    result.nearest_detection = std::numeric_limits<double>::infinity();
    for (const GasDetection& d : detections) {
      result.nearest_detection =
          std::min(result.nearest_detection,
                   horizontal(lag_corrected ? d.lag_corrected : d.position, artifact.position));
    }
    result.found = result.nearest_detection <= radius;
    score.artifacts.push_back(result);
  }
  for (const GasDetection& d : detections) {
    const bool near = std::any_of(
        score.artifacts.begin(), score.artifacts.end(), [&](const GasArtifactResult& a) {
          return horizontal(lag_corrected ? d.lag_corrected : d.position, a.artifact.position) <=
                 radius;
        });
    near ? ++score.true_detections : ++score.false_detections;
  }
  return score;
}

}  // namespace rigdesign::localize
