#include "rigdesign/localize/emitter_localizer.hpp"

#include "rigdesign/localize/wls_multilateration.hpp"

namespace rigdesign::localize {

std::string to_string(LocalizeMethod method) {
  return std::string(model::name_in(kLocalizeMethodNames, method));
}

std::optional<LocalizeMethod> parse_localize_method(const std::string& name) {
  return model::value_in(kLocalizeMethodNames, name);
}

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
              wls_multilateration(estimate.chunks, estimate.geometry.dimensions)) {
        Hypothesis h;
        h.position = solution->position;
        h.covariance = solution->covariance;
        h.rssi_at_1m_dbm = params.path_loss.rssi_at_1m_dbm;
        h.exponent = params.path_loss.exponent;
        estimate.hypotheses.push_back(h);
      }
      break;
    }
    case LocalizeMethod::nls: {
      const RangeFitResult fit =
          fit_ranges(estimate.chunks, estimate.geometry, params.path_loss, params.fit);
      estimate.hypotheses = fit.hypotheses;
      estimate.twin = fit.twin;
      estimate.sigma_db = fit.sigma_db;
      break;
    }
    case LocalizeMethod::map: {
      ObjectMapResult result =
          object_map(estimate.chunks, estimate.geometry, params.path_loss, params.map);
      estimate.hypotheses.push_back(result.estimate);
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
  estimate.bssid = log.emitters.at(static_cast<std::size_t>(emitter));
  for (const RssiReading& reading : log.readings) {
    if (reading.emitter != emitter) continue;
    ++estimate.readings;
    if (reading.rssi_dbm >= params.path_loss.cutoff_dbm) ++estimate.used;
  }
  return estimate;
}

}  // namespace rigdesign::localize
