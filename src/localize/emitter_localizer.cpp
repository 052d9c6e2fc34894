#include "rigdesign/localize/emitter_localizer.hpp"

#include <Eigen/Cholesky>
#include <algorithm>

#include "rigdesign/localize/wls_multilateration.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::localize {

std::string to_string(LocalizeMethod method) {
  return std::string(model::name_in(kLocalizeMethodNames, method));
}

std::optional<LocalizeMethod> parse_localize_method(const std::string& name) {
  return model::value_in(kLocalizeMethodNames, name);
}

namespace {

// The most probable hypothesis on the preferred side that the data cannot tell from the first
// moves to the front; the others keep their order.
void break_tie(const LocalizeParams& params, EmitterEstimate* estimate) {
  const int prefer_side = params.prefer_side;
  if (!estimate->ambiguous || prefer_side == 0) return;
  auto& hypotheses = estimate->hypotheses;
  const Hypothesis first = hypotheses.front();
  const auto preferred =
      std::find_if(hypotheses.begin(), hypotheses.end(), [&](const Hypothesis& h) {
        return h.side == prefer_side && indistinguishable(first, h, params.fit);
      });
  if (preferred != hypotheses.end()) std::rotate(hypotheses.begin(), preferred, preferred + 1);
  estimate->tie_break = std::string("--prefer-side ") + (prefer_side > 0 ? "left" : "right");
}

// The range fit's posterior grid covers the search area: a site, not a continent. The same
// cap as localize --search-area's (10 km sides); a log whose path spans more is refused before
// the grid is sized from it (issue 53: a path across +-1e8 m overflowed the refinement's count).
constexpr double kLargestSearchSide = 10000.0;  // [m]

void check_search_area(const RssiLog& log, const ScanSeries& scans, const RangeFitParams& fit) {
  const std::array<model::Vec2, 2> area = search_area_of(scans, fit);
  const model::Vec2 sides = area[1] - area[0];
  if (sides.x() <= kLargestSearchSide && sides.y() <= kLargestSearchSide) return;
  throw model::InputError(model::Diagnostic{
      {log.source, 0, 0},
      "x, y",
      "the area searched for the emitter (the path's box grown by the search margin) is " +
          model::format_number(sides.x(), 4) + " x " + model::format_number(sides.y(), 4) + " m",
      "a path within 10 km on each side, or --search-area X0 Y0 X1 Y1 of sides up to 10 km"});
}

}  // namespace

EmitterEstimate estimate_from_chunks(std::vector<Chunk> chunks, LocalizeMethod method,
                                     const LocalizeParams& params) {
  EmitterEstimate estimate;
  estimate.method = method;
  estimate.chunks = std::move(chunks);
  if (estimate.chunks.empty()) return estimate;
  estimate.geometry = analyse_geometry(estimate.chunks, params.geometry);
  switch (method) {
    case LocalizeMethod::wls: {
      // Paper 4 as published: one point from the first-sphere linear system.
      if (const auto solution =
              wls_multilateration(estimate.chunks, estimate.geometry.dimensions,
                                  WlsReference::first_chunk, params.chunking.weighting)) {
        Hypothesis h;
        h.position = solution->position;
        h.covariance = solution->covariance;
        h.rssi_at_1m_dbm = params.path_loss.rssi_at_1m_dbm;
        h.exponent = params.path_loss.exponent;
        estimate.hypotheses.push_back(h);
      }
      break;
    }
    case LocalizeMethod::nls: break;  // needs the scans, not the chunks: localize_emitter runs it
    case LocalizeMethod::map: {
      ObjectMapResult result =
          object_map(estimate.chunks, estimate.geometry, params.path_loss, params.map);
      estimate.hypotheses.push_back(result.estimate);
      if (result.map.width > 0) {
        estimate.region =
            make_posterior(result.map.origin, result.map.cell, result.map.width, result.map.height,
                           result.map.log_probability, params.fit.credible_mass);
      }
      estimate.map = std::move(result.map);
      break;
    }
  }
  return estimate;
}

EmitterEstimate localize_emitter(const RssiLog& log, int emitter, LocalizeMethod method,
                                 const LocalizeParams& params) {
  EmitterEstimate estimate = estimate_from_chunks(
      chunk_readings(log, emitter, params.path_loss, params.chunking), method, params);
  if (method == LocalizeMethod::nls) {
    estimate.scans = scan_series(log, emitter, params.scans);
    check_search_area(log, *estimate.scans, params.fit);
    estimate.fit = fit_ranges(*estimate.scans, params.path_loss, params.fit, params.walls);
    estimate.hypotheses = estimate.fit.hypotheses;
    estimate.ambiguous = estimate.fit.ambiguous;
    estimate.region = estimate.fit.posterior;
    estimate.fit.posterior.reset();  // kept once, in region
    break_tie(params, &estimate);
  }
  estimate.bssid = log.emitters.at(static_cast<std::size_t>(emitter));
  for (const RssiReading& reading : log.readings) {
    if (reading.emitter != emitter) continue;
    ++estimate.readings;
    if (reading.heard && passes_cutoff(reading.rssi_dbm, params.path_loss)) ++estimate.used;
  }
  return estimate;
}

bool in_stated_region(const EmitterEstimate& estimate, const model::Vec3& point) {
  if (estimate.region) return estimate.region->contains(point.head<2>());
  if (estimate.hypotheses.empty()) return false;
  const Hypothesis& h = estimate.hypotheses.front();
  const int d = estimate.geometry.dimensions;
  const Eigen::MatrixXd covariance = h.covariance.topLeftCorner(d, d);
  const Eigen::VectorXd offset = (point - h.position).head(d);
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(covariance);
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive() || ldlt.vectorD().minCoeff() <= 0.0)
    return false;
  constexpr double kChi2_95[] = {0, 3.841, 5.991, 7.815};  // by degrees of freedom
  return offset.dot(ldlt.solve(offset)) <= kChi2_95[d];
}

}  // namespace rigdesign::localize
