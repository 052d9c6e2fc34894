#include "rigdesign/deploy/zone_visibility.hpp"

#include <algorithm>
#include <cmath>

#include "rigdesign/model/polygon_area.hpp"

namespace rigdesign::deploy {
namespace {

// [m] a boundary sample this close to the body lies on it: a zone drawn along the robot's
// side, or round a round robot's polygon approximation.
constexpr double kOnBodyTolerance = kBoundaryStep;

// Whether `viewer` sees some point of the obstacle column standing at `p`.
bool sees_column(const ZoneViewer& viewer, const model::Vec2& p, double area_top) {
  const double low = std::max(0.0, viewer.min_z);
  const double high = std::min(area_top, viewer.max_z);
  if (!(high > low)) return false;
  const std::optional<double> azimuth =
      p.norm() > 1e-9 ? std::optional<double>(std::atan2(p.y(), p.x())) : std::nullopt;
  return !viewer.fov
              ->covered_along(model::Vec3(p.x(), p.y(), low), model::Vec3::UnitZ(), 0.0, high - low,
                              azimuth)
              .empty();
}

// One piece of the boundary: its ends and whether it lies on the body or is seen.
struct Piece {
  model::Vec2 from;
  model::Vec2 to;
  bool on_body = false;
  bool seen = false;
};

std::vector<BoundaryArc> unseen_arcs(const std::vector<Piece>& pieces) {
  std::vector<BoundaryArc> arcs;
  bool open = false;
  for (const Piece& piece : pieces) {
    const bool unseen = !piece.on_body && !piece.seen;
    if (unseen && open) {
      arcs.back().to = piece.to;
      arcs.back().length += (piece.to - piece.from).norm();
    } else if (unseen) {
      arcs.push_back({piece.from, piece.to, (piece.to - piece.from).norm()});
    }
    open = unseen;
  }
  // The boundary is closed: an arc running through the first vertex is one arc.
  const bool first_unseen = !pieces.empty() && !pieces.front().on_body && !pieces.front().seen;
  if (open && first_unseen && arcs.size() > 1) {
    arcs.front().from = arcs.back().from;
    arcs.front().length += arcs.back().length;
    arcs.pop_back();
  }
  return arcs;
}

}  // namespace

bool BodyOutline::holds(const model::Vec2& p, double tolerance) const {
  if (hull.empty()) return p.norm() <= radius + tolerance;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const model::Vec2 edge = hull[(i + 1) % hull.size()] - hull[i];
    const double length = edge.norm();
    if (length == 0.0) continue;
    // Distance of p to the left of the edge (inside for a counter-clockwise hull).
    const double left =
        (edge.x() * (p.y() - hull[i].y()) - edge.y() * (p.x() - hull[i].x())) / length;
    if (left < -tolerance) return false;
  }
  return true;
}

ZoneVisibility zone_visibility(const std::vector<model::Vec2>& given, const BodyOutline& body,
                               const std::vector<ZoneViewer>& viewers, double area_top) {
  // Arcs run counter-clockwise whichever way the file winds its polygon.
  std::vector<model::Vec2> zone = given;
  if (model::signed_area(zone) < 0.0) std::reverse(zone.begin(), zone.end());
  ZoneVisibility visibility;
  visibility.sees.assign(viewers.size(), false);
  visibility.seen_boundary.assign(viewers.size(), 0.0);
  if (zone.size() < 3) return visibility;
  std::vector<Piece> pieces;
  for (std::size_t i = 0; i < zone.size(); ++i) {
    const model::Vec2& a = zone[i];
    const model::Vec2& b = zone[(i + 1) % zone.size()];
    const double length = (b - a).norm();
    const int count = std::max(1, static_cast<int>(std::ceil(length / kBoundaryStep)));
    for (int k = 0; k < count; ++k) {
      Piece piece{a + (b - a) * (static_cast<double>(k) / count),
                  a + (b - a) * (static_cast<double>(k + 1) / count)};
      const model::Vec2 middle = (piece.from + piece.to) / 2.0;
      piece.on_body = body.holds(middle, kOnBodyTolerance);
      if (!piece.on_body) {
        visibility.checked_boundary += length / count;
        for (std::size_t v = 0; v < viewers.size(); ++v) {
          if (!sees_column(viewers[v], middle, area_top)) continue;
          piece.seen = true;
          visibility.sees[v] = true;
          visibility.seen_boundary[v] += length / count;
        }
      }
      pieces.push_back(piece);
    }
  }
  visibility.unseen = unseen_arcs(pieces);
  // A source may see only the zone's inside (a camera looking down into it): it still feeds it.
  model::Vec2 low = zone.front();
  model::Vec2 high = zone.front();
  for (const model::Vec2& p : zone) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  for (std::size_t v = 0; v < viewers.size(); ++v) {
    for (double x = low.x() + kInteriorStep / 2; x < high.x() && !visibility.sees[v];
         x += kInteriorStep) {
      for (double y = low.y() + kInteriorStep / 2; y < high.y(); y += kInteriorStep) {
        const model::Vec2 p(x, y);
        if (!model::inside_polygon(zone, p) || body.holds(p, 0.0)) continue;
        if (sees_column(viewers[v], p, area_top)) {
          visibility.sees[v] = true;
          break;
        }
      }
    }
  }
  return visibility;
}

}  // namespace rigdesign::deploy
