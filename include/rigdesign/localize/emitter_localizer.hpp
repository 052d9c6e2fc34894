#pragma once
/// One emitter's position from a log by one of three methods: paper 4's linearised weighted
/// least squares (`wls`), the dB-domain range fit (`nls`) or paper 4's object map (`map`),
/// all on the same chunks of the readings at or above the cut-off.
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/localize/chunking.hpp"
#include "rigdesign/localize/geometry_analysis.hpp"
#include "rigdesign/localize/hypothesis.hpp"
#include "rigdesign/localize/object_map.hpp"
#include "rigdesign/localize/path_loss.hpp"
#include "rigdesign/localize/range_fit.hpp"
#include "rigdesign/localize/rssi_log.hpp"
#include "rigdesign/model/name_table.hpp"

namespace rigdesign::localize {

enum class LocalizeMethod { wls, nls, map };
inline constexpr model::NameTable<LocalizeMethod, 3> kLocalizeMethodNames = {{
    {LocalizeMethod::wls, "wls"},
    {LocalizeMethod::nls, "nls"},
    {LocalizeMethod::map, "map"},
}};
static_assert(model::covers_in_order(kLocalizeMethodNames) &&
              kLocalizeMethodNames.size() == static_cast<std::size_t>(LocalizeMethod::map) + 1);

std::string to_string(LocalizeMethod method);
/// "wls", "nls" or "map".
std::optional<LocalizeMethod> parse_localize_method(const std::string& name);

struct LocalizeParams {
  PathLossParams path_loss;
  ChunkParams chunking;
  GeometryParams geometry;
  RangeFitParams fit;
  ObjectMapParams map;
};

struct EmitterEstimate {
  std::string bssid;
  LocalizeMethod method = LocalizeMethod::nls;
  int readings = 0;  ///< the emitter's readings in the log
  int used = 0;      ///< of which at or above the cut-off
  std::vector<Chunk> chunks;
  GeometryAnalysis geometry;
  /// Best first; two when the geometry or the fit leaves a twin; empty when the method could
  /// not solve (too few chunks, or a singular linear system).
  std::vector<Hypothesis> hypotheses;
  bool twin = false;
  double sigma_db = 0.0;         ///< residual standard deviation per chunk (nls) [dB]
  std::optional<ObjectMap> map;  ///< the probability grid (map)
};

/// Runs `method` on one emitter's chunks (chunks and geometry as computed here).
EmitterEstimate estimate_from_chunks(std::vector<Chunk> chunks, LocalizeMethod method,
                                     const LocalizeParams& params);

/// The emitter with index `emitter` in `log`.
EmitterEstimate localize_emitter(const RssiLog& log, int emitter, LocalizeMethod method,
                                 const LocalizeParams& params = {});

}  // namespace rigdesign::localize
