#pragma once
/// Whether a polygon an input gives (a footprint, a protective zone) can be judged at all
/// (issue 53 item 6): a zone that crosses itself has no inside, one with no area has no
/// boundary to enter through, one with a corner beyond the coordinate limit overflows the
/// arithmetic that follows. Checked where the polygon is read, so the refusal names its line.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::model {

/// Most corners a polygon may have: the self-crossing test compares every pair of edges.
inline constexpr std::size_t kMaxPolygonCorners = 4096;

/// Why `polygon` is unusable ("has 2 corners", "encloses no area", "edge 0-1 crosses edge
/// 2-3", ...), or nothing when it is a simple polygon with an area within +-kMaxCoordinate.
std::optional<std::string> polygon_problem(const std::vector<Vec2>& polygon);

}  // namespace rigdesign::model
