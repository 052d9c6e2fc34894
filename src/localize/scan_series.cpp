#include "rigdesign/localize/scan_series.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/statistics.hpp"

namespace rigdesign::localize {
namespace {

// One scan of the receiver: the log lines of every emitter within half a scan period of its
// first line.
struct ScanEvent {
  double t = 0.0;
  model::Vec3 position = model::Vec3::Zero();
  std::optional<double> rssi_dbm;  // this emitter, when heard
  bool logged_unheard = false;     // an empty-rssi line for this emitter
};

// Median step between consecutive lines of the same emitter, pooled over emitters: gaps where
// an emitter was not heard are longer steps, which the median ignores while most scans hear.
double median_scan_step(const RssiLog& log) {
  std::vector<double> last(log.emitters.size(), std::numeric_limits<double>::quiet_NaN());
  std::vector<double> steps;
  for (const RssiReading& r : log.readings) {
    double& previous = last[static_cast<std::size_t>(r.emitter)];
    if (!std::isnan(previous) && r.t > previous) steps.push_back(r.t - previous);
    previous = r.t;
  }
  return steps.empty() ? 0.0 : model::median(steps);
}

std::vector<ScanEvent> scan_events(const RssiLog& log, int emitter, double period) {
  std::vector<const RssiReading*> sorted;
  sorted.reserve(log.readings.size());
  for (const RssiReading& r : log.readings) sorted.push_back(&r);
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const RssiReading* a, const RssiReading* b) { return a->t < b->t; });
  std::vector<ScanEvent> events;
  int lines = 0;
  for (const RssiReading* r : sorted) {
    if (events.empty() || r->t - events.back().t > 0.5 * period) {
      events.push_back({r->t, model::Vec3::Zero(), std::nullopt, false});
      lines = 0;
    }
    ScanEvent& event = events.back();
    event.position = (event.position * lines + r->position) / (lines + 1);
    ++lines;
    if (r->emitter != emitter) continue;
    if (r->heard) {
      // Two readings of one emitter in one scan: keep their mean in dB.
      event.rssi_dbm = event.rssi_dbm ? 0.5 * (*event.rssi_dbm + r->rssi_dbm) : r->rssi_dbm;
    } else {
      event.logged_unheard = true;
    }
  }
  return events;
}

double weakest_reading(const RssiLog& log) {
  double weakest = std::numeric_limits<double>::infinity();
  for (const RssiReading& r : log.readings)
    if (r.heard) weakest = std::min(weakest, r.rssi_dbm);
  return std::isfinite(weakest) ? weakest : std::numeric_limits<double>::lowest();
}

// Unheard scans a series may hold between its log lines, in all: a scan every 0.1 s for 11
// days, about 0.5 GB of scans. More means timestamps in another unit than seconds or a scan
// period far shorter than the log's (issue 53: a 1e8 s gap in a 0.1 s log ran out of memory).
constexpr double kMaxMissedScans = 1e7;

// The scans missed between lines at `from` and `to` [s], judged in floating point against the
// cap before they become an integer.
int missed_scans(const RssiLog& log, double from, double to, double period,
                 const ScanSeries& series) {
  const double missed = std::round((to - from) / period) - 1.0;
  const double so_far = series.unheard_interpolated + series.unheard_unplaced;
  if (!(missed + so_far <= kMaxMissedScans)) {
    using model::format_number;
    throw model::InputError(model::Diagnostic{
        {log.source, 0, 0},
        "t",
        "the gap from t = " + format_number(from) + " s to " + format_number(to) + " s is " +
            format_number(missed, 3) + " scan periods of " + format_number(period) +
            " s: more than " + format_number(kMaxMissedScans) + " scans to place in all",
        "timestamps in seconds and a scan period that fits them (--scan-period or the log's "
        "'# scan_period_s:')"});
  }
  return static_cast<int>(missed);
}

}  // namespace

std::string to_string(FloorSource source) {
  switch (source) {
    case FloorSource::log: return "the log's floor_dbm";
    case FloorSource::option: return "--floor";
    case FloorSource::weakest_reading: return "the weakest reading in the log (no floor given)";
  }
  return "";
}

ScanSeries scan_series(const RssiLog& log, int emitter, const ScanSeriesParams& params) {
  ScanSeries series;
  if (params.floor_dbm) {
    series.floor_dbm = *params.floor_dbm;
    series.floor_source = FloorSource::option;
  } else if (log.floor_dbm) {
    series.floor_dbm = *log.floor_dbm;
    series.floor_source = FloorSource::log;
  } else {
    series.floor_dbm = weakest_reading(log);
  }
  series.scan_period_s = params.scan_period_s ? *params.scan_period_s
                         : log.scan_period_s  ? *log.scan_period_s
                                              : median_scan_step(log);
  const double period = series.scan_period_s;
  const std::vector<ScanEvent> events = scan_events(log, emitter, period);

  // The robot's median speed between scans one period apart: what a straight gap must match.
  std::vector<double> speeds;
  for (std::size_t k = 1; k < events.size(); ++k) {
    const double dt = events[k].t - events[k - 1].t;
    if (dt > 0 && dt <= 1.5 * period)
      speeds.push_back((events[k].position - events[k - 1].position).head<2>().norm() / dt);
  }
  const double speed = speeds.empty() ? 0.0 : model::median(speeds);

  for (std::size_t k = 0; k < events.size(); ++k) {
    const ScanEvent& event = events[k];
    if (k > 0 && period > 0) {
      const ScanEvent& before = events[k - 1];
      const double dt = event.t - before.t;
      const int missed = missed_scans(log, before.t, event.t, period, series);
      if (missed > 0) {
        const double chord = (event.position - before.position).head<2>().norm();
        constexpr double kStandingStill = 0.05;  // [m] covered in the gap: no path to know
        const double expected = speed * dt;
        const bool straight =
            expected < kStandingStill || chord >= params.min_straightness * expected;
        if (straight) {
          for (int i = 1; i <= missed; ++i) {
            const double share = static_cast<double>(i) / (missed + 1);
            series.scans.push_back({before.t + share * dt,
                                    before.position + share * (event.position - before.position),
                                    0.0, false});
          }
          series.unheard_interpolated += missed;
        } else {
          series.unheard_unplaced += missed;
        }
      }
    }
    if (event.rssi_dbm) {
      series.scans.push_back({event.t, event.position, *event.rssi_dbm, true});
      ++series.heard;
    } else {
      series.scans.push_back({event.t, event.position, 0.0, false});
      ++series.unheard_logged;
    }
  }
  return series;
}

}  // namespace rigdesign::localize
