#pragma once
/// One emitter's position from a log by one of three methods: paper 4's linearised weighted
/// least squares (`wls`) and object map (`map`), both on the chunks of the readings stronger
/// than the cut-off as the paper does, and the range fit (`nls`) on every scan, heard or not.
/// Each states a 95 % region: wls its Gaussian ellipse, map and nls the highest-density
/// region of their grids.
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
#include "rigdesign/localize/scan_series.hpp"
#include "rigdesign/localize/walls.hpp"
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
  ScanSeriesParams scans;
  RangeFitParams fit;
  ObjectMapParams map;
  std::vector<WallSegment> walls;  ///< a map the range fit models (`--walls`)
  /// +1 left, -1 right of the path (REP-103, facing the direction of travel): which of
  /// ambiguous hypotheses to list first (`--prefer-side`); 0: none.
  int prefer_side = 0;
};

struct EmitterEstimate {
  std::string bssid;
  LocalizeMethod method = LocalizeMethod::nls;
  int readings = 0;  ///< the emitter's readings in the log
  int used = 0;      ///< of which stronger than the cut-off (paper 4's methods use these)
  std::vector<Chunk> chunks;
  GeometryAnalysis geometry;
  /// Most probable first; empty when the method could not solve (too few chunks, a singular
  /// linear system, nothing heard).
  std::vector<Hypothesis> hypotheses;
  /// The first two hypotheses are indistinguishable (nls): their order is not evidence.
  bool ambiguous = false;
  /// What put the first hypothesis first when ambiguous: "--prefer-side left", or empty.
  std::string tie_break;
  std::optional<ObjectMap> map;             ///< the probability grid (map)
  std::optional<PositionPosterior> region;  ///< its grid with the 95 % region (nls, map)
  std::optional<ScanSeries> scans;          ///< the scans the range fit used (nls)
  RangeFitResult fit;                       ///< noise and exponent findings (nls)
};

/// Whether `point` lies in the estimate's stated 95 % region (wls: the first hypothesis'
/// ellipse, chi-square 5.99 for 2 d.o.f.; nls and map: their highest-density region), with
/// horizontal distances as everywhere when z is unobservable.
bool in_stated_region(const EmitterEstimate& estimate, const model::Vec3& point);

/// Runs `method` on one emitter's chunks (chunks and geometry as computed here).
EmitterEstimate estimate_from_chunks(std::vector<Chunk> chunks, LocalizeMethod method,
                                     const LocalizeParams& params);

/// The emitter with index `emitter` in `log`.
EmitterEstimate localize_emitter(const RssiLog& log, int emitter, LocalizeMethod method,
                                 const LocalizeParams& params = {});

}  // namespace rigdesign::localize
