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

// [m] how far from the robot's axis any viewer can see: beyond it every column is unseen,
// so only the part of a zone within it is sampled (a zone typed in millimetres, 860 m wide,
// costs what its part within the sensors' reach costs).
double viewers_reach(const std::vector<ZoneViewer>& viewers) {
  double reach = 0.0;
  for (const ZoneViewer& viewer : viewers)
    reach = std::max(reach, viewer.fov->origin().head<2>().norm() + viewer.fov->mode().max_range);
  return reach;
}

// The parameters [t0, t1] within [0, 1] at which a + t (b - a) lies within `reach` of the
// axis, or nothing.
std::optional<std::pair<double, double>> within_reach(const model::Vec2& a, const model::Vec2& b,
                                                      double reach) {
  const model::Vec2 d = b - a;
  const double dd = d.squaredNorm();
  if (dd == 0.0) return a.norm() <= reach ? std::optional(std::pair(0.0, 1.0)) : std::nullopt;
  // |a + t d|^2 = reach^2: dd t^2 + 2 (a.d) t + |a|^2 - reach^2 = 0.
  const double half_b = a.dot(d);
  const double disc = half_b * half_b - dd * (a.squaredNorm() - reach * reach);
  if (disc < 0.0) return std::nullopt;
  const double root = std::sqrt(disc);
  const double t0 = std::max(0.0, (-half_b - root) / dd);
  const double t1 = std::min(1.0, (-half_b + root) / dd);
  if (!(t0 < t1)) return std::nullopt;
  return std::pair(t0, t1);
}

// The edge a -> b cut into pieces: kBoundaryStep apart within reach, one unseen piece for each
// stretch beyond it.
void edge_pieces(const model::Vec2& a, const model::Vec2& b, double reach,
                 std::vector<Piece>& pieces) {
  const auto at = [&](double t) -> model::Vec2 { return a + (b - a) * t; };
  const auto span = within_reach(a, b, reach);
  if (!span) {
    pieces.push_back({a, b});
    return;
  }
  if (span->first > 0.0) pieces.push_back({a, at(span->first)});
  // Judged as a double first: a source of absurd range puts a whole 1e8 m edge within reach.
  const double length = (b - a).norm() * (span->second - span->first);
  const int count =
      static_cast<int>(std::clamp(std::ceil(length / kBoundaryStep), 1.0, kMaxEdgeSamples));
  for (int k = 0; k < count; ++k) {
    const double step = (span->second - span->first) / count;
    pieces.push_back({at(span->first + step * k), at(span->first + step * (k + 1))});
  }
  if (span->second < 1.0) pieces.push_back({at(span->second), b});
}

// A source may see only the zone's inside (a camera looking down into it): it still feeds it.
// The inside is sampled within the viewers' reach only, every kInteriorStep, or coarser so
// that no viewer tries more than kMaxInteriorSamples columns.
void interior_sightings(const std::vector<model::Vec2>& zone, const BodyOutline& body,
                        const std::vector<ZoneViewer>& viewers, double area_top, double reach,
                        ZoneVisibility& visibility) {
  model::Vec2 low = zone.front();
  model::Vec2 high = zone.front();
  for (const model::Vec2& p : zone) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  low = low.cwiseMax(model::Vec2(-reach, -reach));
  high = high.cwiseMin(model::Vec2(reach, reach));
  if (!(low.x() < high.x() && low.y() < high.y())) return;
  const double area = (high.x() - low.x()) * (high.y() - low.y());
  const double step = std::max(kInteriorStep, std::sqrt(area / kMaxInteriorSamples));
  // At most 1e6 columns in all: the counts fit an int.
  const int columns = static_cast<int>(std::ceil((high.x() - low.x()) / step));
  const int rows = static_cast<int>(std::ceil((high.y() - low.y()) / step));
  for (std::size_t v = 0; v < viewers.size(); ++v) {
    for (int i = 0; i < columns && !visibility.sees[v]; ++i) {
      for (int j = 0; j < rows; ++j) {
        const model::Vec2 p(low.x() + (i + 0.5) * step, low.y() + (j + 0.5) * step);
        if (!model::inside_polygon(zone, p) || body.holds(p, 0.0)) continue;
        if (sees_column(viewers[v], p, area_top)) {
          visibility.sees[v] = true;
          break;
        }
      }
    }
  }
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
  const double reach = viewers_reach(viewers);
  std::vector<Piece> pieces;
  for (std::size_t i = 0; i < zone.size(); ++i)
    edge_pieces(zone[i], zone[(i + 1) % zone.size()], reach, pieces);
  for (Piece& piece : pieces) {
    const model::Vec2 middle = (piece.from + piece.to) / 2.0;
    const double length = (piece.to - piece.from).norm();
    piece.on_body = body.holds(middle, kOnBodyTolerance);
    if (piece.on_body) continue;
    visibility.checked_boundary += length;
    for (std::size_t v = 0; v < viewers.size() && middle.norm() <= reach; ++v) {
      if (!sees_column(viewers[v], middle, area_top)) continue;
      piece.seen = true;
      visibility.sees[v] = true;
      visibility.seen_boundary[v] += length;
    }
  }
  visibility.unseen = unseen_arcs(pieces);
  interior_sightings(zone, body, viewers, area_top, reach, visibility);
  return visibility;
}

}  // namespace rigdesign::deploy
