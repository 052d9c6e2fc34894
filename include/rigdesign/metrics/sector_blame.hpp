#pragma once
/// What a sector's verdict rests on at its worst angle (issue 39: CI annotations on the line a
/// reviewer must change): each mount's share of the section there is cut exactly twice, behind
/// the body and with the body transparent. The mount that would see most is the one to blame;
/// when the body hides part of what it would see, the body is (the description's part that
/// hides most, or the rig's `body`).
#include <optional>
#include <string>

#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::metrics {

struct SectorBlame {
  std::optional<std::size_t> mount;  ///< index in the rig; nothing: no mount would see there
  bool body = false;  ///< the body or another sensor's housing hides part of that view
  /// The description's link whose part hides most, or the housing's name
  /// (geometry::housing_part_name) when `by_housing`.
  std::string part;
  bool by_housing = false;
  model::SourceLocation where;  ///< the line to annotate
  double hidden = 0.0;          ///< share of the section (or floor) the body hides from it
};

/// At azimuth `theta` [rad], for the share the verdict rests on (`floor`: SC floor, else SC
/// complete). Precondition as compute_coverage.
SectorBlame sector_blame(const model::Rig& rig, const model::SensorLibrary& library, double theta,
                         bool floor);

}  // namespace rigdesign::metrics
