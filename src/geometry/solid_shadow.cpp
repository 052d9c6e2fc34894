#include "rigdesign/geometry/solid_shadow.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rigdesign/geometry/winding_number.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::geometry {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
// Azimuth bins for culling: a triangle is tried in a section only if its shadow's azimuth
// span (about the robot's vertical axis) overlaps the section's bin.
constexpr int kAzimuthBins = 720;

}  // namespace

SolidShadow::SolidShadow(const std::vector<model::BodyPart>& parts,
                         const std::vector<model::BodyPart>& other_housings,
                         const model::Vec3& origin, const std::string& housing,
                         const TriangleTest& may_matter)
    : origin_(origin), bins_(kAzimuthBins) {
  for (const auto* group : {&parts, &other_housings}) {
    for (const model::BodyPart& part : *group) {
      if (!housing.empty() && part.link == housing) continue;
      if (!add_part(part, may_matter)) return;  // every line is blocked whole
    }
  }
}

bool SolidShadow::add_part(const model::BodyPart& part, const TriangleTest& may_matter) {
  if (inside_part(part, origin_)) {
    buried_in_ = part.link;
    return false;
  }
  if (part.cylinder) {
    const model::VerticalCylinder& c = *part.cylinder;
    model::RobotBody solid;
    solid.radius = c.radius;
    solid.height = c.z_max - c.z_min;
    cylinders_.push_back({BodyOccluder(solid), model::Vec3(c.centre.x(), c.centre.y(), c.z_min)});
    return true;
  }
  const model::TriangleMesh& mesh = part.triangles;
  for (const auto& t : mesh.triangles) {
    const model::Vec3& a = mesh.vertices[t[0]];
    const model::Vec3& b = mesh.vertices[t[1]];
    const model::Vec3& c = mesh.vertices[t[2]];
    if (may_matter && !may_matter(a, b, c)) continue;
    add_triangle(a, b, c);
  }
  return true;
}

void SolidShadow::add_triangle(const model::Vec3& a, const model::Vec3& b, const model::Vec3& c) {
  const model::Vec3 e[3] = {a - origin_, b - origin_, c - origin_};
  model::Vec3 plane = (b - a).cross(c - a);
  double beyond = plane.dot(e[0]);
  // Seen edge-on (the origin in its plane) a triangle hides a set of no volume.
  if (std::abs(beyond) <= 1e-12 * plane.norm() * e[0].norm() || plane.norm() < 1e-18) return;
  if (beyond < 0) {
    plane = -plane;
    beyond = -beyond;
  }
  TriangleShadow shadow;
  for (int i = 0; i < 3; ++i) {
    model::Vec3 n = e[i].cross(e[(i + 1) % 3]);
    if (n.dot(e[(i + 2) % 3]) < 0) n = -n;  // inward: the third corner's side
    shadow.normal[i] = n;
    shadow.offset[i] = 0.0;
  }
  shadow.normal[3] = plane;
  shadow.offset[3] = beyond;
  triangles_.push_back(shadow);
  const int index = static_cast<int>(triangles_.size()) - 1;
  all_.push_back(index);
  const model::Vec3 corners[3] = {a, b, c};
  bin_by_azimuth(static_cast<std::size_t>(index), corners);
}

// The shadow's horizontal projection is the convex hull of the corners plus the rays from
// them away from the origin; if it misses the robot's axis it lies in a half-plane and spans
// the arc covering its generators' azimuths (corners and ray directions).
void SolidShadow::bin_by_azimuth(std::size_t index, const model::Vec3 corners[3]) {
  std::vector<double> azimuths;
  bool everywhere = false;
  for (int i = 0; i < 3 && !everywhere; ++i) {
    const model::Vec2 corner = corners[i].head<2>();
    const model::Vec2 ray = corner - origin_.head<2>();
    if (corner.norm() < 1e-9) everywhere = true;
    azimuths.push_back(model::wrap_angle(std::atan2(corner.y(), corner.x())));
    if (ray.norm() > 1e-12) azimuths.push_back(model::wrap_angle(std::atan2(ray.y(), ray.x())));
  }
  double from = 0.0;
  double span = kTwoPi;
  if (!everywhere) {
    std::sort(azimuths.begin(), azimuths.end());
    double widest = azimuths.front() + kTwoPi - azimuths.back();
    from = azimuths.front();
    for (std::size_t i = 1; i < azimuths.size(); ++i) {
      if (azimuths[i] - azimuths[i - 1] > widest) {
        widest = azimuths[i] - azimuths[i - 1];
        from = azimuths[i];
      }
    }
    span = kTwoPi - widest;
    if (span >= std::numbers::pi - 1e-9) span = kTwoPi;
  }
  const double bin_width = kTwoPi / kAzimuthBins;
  if (span >= kTwoPi) {
    for (auto& bin : bins_) bin.push_back(static_cast<int>(index));
    return;
  }
  // One bin of margin on each side absorbs rounding at the bin edges.
  const int first = static_cast<int>(std::floor(from / bin_width)) - 1;
  const int last = static_cast<int>(std::floor((from + span) / bin_width)) + 1;
  for (int k = first; k <= last; ++k) {
    bins_[static_cast<std::size_t>((k % kAzimuthBins + kAzimuthBins) % kAzimuthBins)].push_back(
        static_cast<int>(index));
  }
}

const std::vector<int>& SolidShadow::candidates(std::optional<double> section_azimuth) const {
  if (!section_azimuth) return all_;
  const int bin =
      static_cast<int>(std::floor(model::wrap_angle(*section_azimuth) / (kTwoPi / kAzimuthBins)));
  return bins_[static_cast<std::size_t>(std::clamp(bin, 0, kAzimuthBins - 1))];
}

IntervalSet SolidShadow::blocked_along(const model::Vec3& start, const model::Vec3& direction,
                                       double t_min, double t_max,
                                       std::optional<double> section_azimuth) const {
  if (!buried_in_.empty()) {
    IntervalSet whole;
    whole.append(t_min, t_max);
    return whole;
  }
  thread_local std::vector<IntervalSet::Interval> pieces;
  pieces.clear();
  const model::Vec3 c = start - origin_;
  for (const int index : candidates(section_azimuth)) {
    const TriangleShadow& shadow = triangles_[static_cast<std::size_t>(index)];
    double low = t_min;
    double high = t_max;
    for (int k = 0; k < 4 && low < high; ++k) {
      const double value = shadow.normal[k].dot(c) - shadow.offset[k];
      const double slope = shadow.normal[k].dot(direction);
      if (slope == 0.0) {
        if (value < 0) high = low;
      } else if (slope > 0) {
        low = std::max(low, -value / slope);
      } else {
        high = std::min(high, -value / slope);
      }
    }
    if (high - low > kShortestPiece) pieces.emplace_back(low, high);  // shorter: grazing
  }
  thread_local std::vector<double> cuts;
  for (const CylinderShadow& cylinder : cylinders_) {
    const model::Vec3 o = origin_ - cylinder.to_local;
    const model::Vec3 s = start - cylinder.to_local;
    cuts.assign({t_min, t_max});
    cylinder.solid.append_critical_parameters(o, s, direction, cuts);
    for_each_piece(cuts, t_min, t_max, [&](double low, double high) {
      if (cylinder.solid.blocks(o, s + 0.5 * (low + high) * direction)) {
        pieces.emplace_back(low, high);
      }
    });
  }
  std::sort(pieces.begin(), pieces.end());
  IntervalSet blocked;
  for (const auto& [low, high] : pieces) blocked.append(low, high);
  return blocked;
}

bool SolidShadow::blocks(const model::Vec3& point) const {
  if (!buried_in_.empty()) return true;
  const model::Vec3 q = point - origin_;
  for (const TriangleShadow& shadow : triangles_) {
    bool inside = true;
    for (int k = 0; k < 4 && inside; ++k) inside = shadow.normal[k].dot(q) > shadow.offset[k];
    if (inside) return true;
  }
  for (const CylinderShadow& cylinder : cylinders_) {
    if (cylinder.solid.blocks(origin_ - cylinder.to_local, point - cylinder.to_local)) return true;
  }
  return false;
}

}  // namespace rigdesign::geometry
