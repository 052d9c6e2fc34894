#include "rigdesign/geometry/body_occluder.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rigdesign/model/line_crossings.hpp"
#include "rigdesign/model/polygon_area.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::geometry {
namespace {

// Azimuth bins of the outline's edge index (0.5 degree).
constexpr int kOutlineBins = 720;
// Sight lines shorter than this inside the body (m) are grazing contacts, not occlusion.
constexpr double kGrazing = 1e-9;

double cross2(const model::Vec2& a, const model::Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Where the lines a + s d and p + t e meet: false when they are parallel.
bool line_crossing(const model::Vec2& a, const model::Vec2& d, const model::Vec2& p,
                   const model::Vec2& e, double& s, double& t) {
  const double denominator = cross2(d, e);
  if (std::abs(denominator) < 1e-15) return false;
  s = cross2(p - a, e) / denominator;
  t = cross2(p - a, d) / denominator;
  return true;
}

// Parameters s in [0, 1] where the 2D segment a + s (b - a) crosses the polygon's edges.
void edge_crossings(const std::vector<model::Vec2>& polygon, const model::Vec2& a,
                    const model::Vec2& b, std::vector<double>& crossings) {
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const model::Vec2& p = polygon[i];
    double s = 0.0;
    double along_edge = 0.0;
    if (line_crossing(a, b - a, p, polygon[(i + 1) % polygon.size()] - p, s, along_edge) &&
        s >= 0 && s <= 1 && along_edge >= 0 && along_edge <= 1) {
      crossings.push_back(s);
    }
  }
}

// Longest stretch of s in (0, 1) where the segment is inside the body's horizontal
// cross-section and also within [low, high] (the slab 0 < z < h mapped to s).
bool overlaps_inside(const std::vector<model::Vec2>& polygon, const model::Vec2& a,
                     const model::Vec2& b, double low, double high) {
  std::vector<double> cuts = {0.0, 1.0};
  edge_crossings(polygon, a, b, cuts);
  std::sort(cuts.begin(), cuts.end());
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double from = std::max(cuts[i], low);
    const double to = std::min(cuts[i + 1], high);
    if (to - from <= kGrazing) continue;
    const double mid = 0.5 * (cuts[i] + cuts[i + 1]);
    if (model::inside_polygon(polygon, a + mid * (b - a))) return true;
  }
  return false;
}

}  // namespace

BodyOccluder::BodyOccluder(const model::RobotBody& body)
    : radius_(body.radius),
      height_(body.height),
      area_top_(body.area_top()),
      footprint_(body.footprint),
      parts_(body.has_parts() ? &body.parts : nullptr) {
  if (parts_) bin_outline_edges();
}

void BodyOccluder::bin_outline_edges() {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  outline_bins_.assign(kOutlineBins, {});
  const double width = kTwoPi / kOutlineBins;
  for (const model::BodyPart& part : *parts_) {
    const model::TriangleMesh& mesh = part.triangles;
    for (const auto& t : mesh.triangles) {
      for (int i = 0; i < 3; ++i) {
        const Edge edge{mesh.vertices[t[i]].head<2>(), mesh.vertices[t[(i + 1) % 3]].head<2>()};
        if (edge.a.norm() < 1e-12 || edge.b.norm() < 1e-12) {
          for (auto& bin : outline_bins_) bin.push_back(edge);
          continue;
        }
        // A segment not through the axis spans the shorter arc between its ends' azimuths.
        double from = model::wrap_angle(std::atan2(edge.a.y(), edge.a.x()));
        double span = model::wrap_angle(std::atan2(edge.b.y(), edge.b.x()) - from);
        if (span > std::numbers::pi) {
          from = model::wrap_angle(from + span);
          span = kTwoPi - span;
        }
        const int first = static_cast<int>(std::floor(from / width)) - 1;
        const int last = static_cast<int>(std::floor((from + span) / width)) + 1;
        for (int k = first; k <= last; ++k) {
          outline_bins_[static_cast<std::size_t>((k % kOutlineBins + kOutlineBins) % kOutlineBins)]
              .push_back(edge);
        }
      }
    }
  }
}

bool BodyOccluder::blocks(const model::Vec3& origin, const model::Vec3& point) const {
  if (parts_) return false;
  const model::Vec3 d = point - origin;
  // Slab 0 < z < h along s in (0, 1).
  double low = 0.0;
  double high = 1.0;
  if (std::abs(d.z()) < 1e-15) {
    if (origin.z() <= 0.0 || origin.z() >= height_) return false;
  } else {
    const double s0 = (0.0 - origin.z()) / d.z();
    const double s1 = (height_ - origin.z()) / d.z();
    low = std::max(low, std::min(s0, s1));
    high = std::min(high, std::max(s0, s1));
  }
  if (high - low <= kGrazing) return false;
  const model::Vec2 a = origin.head<2>();
  const model::Vec2 b = point.head<2>();
  if (!footprint_.empty()) return overlaps_inside(footprint_, a, b, low, high);
  const model::Vec2 dxy = b - a;
  const double qa = dxy.squaredNorm();
  const double qb = 2 * a.dot(dxy);
  const double qc = a.squaredNorm() - radius_ * radius_;
  if (qa < 1e-18) return qc < 0;  // vertical sight line
  const double discriminant = qb * qb - 4 * qa * qc;
  if (discriminant <= 0) return false;
  const double root = std::sqrt(discriminant);
  const double enter = (-qb - root) / (2 * qa);
  const double leave = (-qb + root) / (2 * qa);
  return std::min(high, leave) - std::max(low, enter) > kGrazing;
}

void BodyOccluder::append_critical_parameters(const model::Vec3& origin, const model::Vec3& start,
                                              const model::Vec3& direction,
                                              std::vector<double>& parameters) const {
  if (parts_) return;
  const model::Vec3 e =
      start - origin;  // sight vector at t = 0; it grows by `direction` per unit t
  const auto plane_root = [&](const model::Vec3& normal) {
    const double slope = normal.dot(direction);
    if (std::abs(slope) > 1e-15) parameters.push_back(-normal.dot(e) / slope);
  };
  const model::Vec2 o = origin.head<2>();
  if (!footprint_.empty()) {
    for (std::size_t i = 0; i < footprint_.size(); ++i) {
      const model::Vec2& vertex = footprint_[i];
      const model::Vec2& next = footprint_[(i + 1) % footprint_.size()];
      const model::Vec2 toward = vertex - o;
      plane_root(
          model::Vec3(-toward.y(), toward.x(), 0.0));  // vertical plane through the edge line
      for (const double z : {0.0, height_}) {          // planes through the face edges
        const model::Vec3 p(vertex.x(), vertex.y(), z);
        const model::Vec3 q(next.x(), next.y(), z);
        plane_root((p - origin).cross(q - origin));
      }
    }
    return;
  }
  const double distance = o.norm();
  if (distance > radius_) {  // vertical tangent planes of the side
    const model::Vec2 unit = o / distance;
    const model::Vec2 across(-unit.y(), unit.x());
    const double along = radius_ * radius_ / distance;
    const double aside = radius_ * std::sqrt(distance * distance - radius_ * radius_) / distance;
    for (const double sign : {-1.0, 1.0}) {
      const model::Vec2 toward = unit * along + sign * aside * across - o;
      plane_root(model::Vec3(-toward.y(), toward.x(), 0.0));
    }
  }
  // Cones from the origin through the top and bottom rims: sight q meets the plane z = z_rim
  // at o + k q_xy / q_z (k = z_rim - o_z), on the rim when |o q_z + k q_xy|^2 = r^2 q_z^2.
  for (const double rim : {0.0, height_}) {
    const double k = rim - origin.z();
    const model::Vec2 f0 = o * e.z() + k * e.head<2>();
    const model::Vec2 f1 = o * direction.z() + k * direction.head<2>();
    const double r2 = radius_ * radius_;
    model::append_quadratic_roots(f1.squaredNorm() - r2 * direction.z() * direction.z(),
                                  2 * f0.dot(f1) - 2 * r2 * e.z() * direction.z(),
                                  f0.squaredNorm() - r2 * e.z() * e.z(), parameters);
  }
}

bool BodyOccluder::contains(const model::Vec3& point) const {
  if (parts_) return false;
  constexpr double kSurface = 1e-9;
  if (point.z() <= kSurface || point.z() >= height_ - kSurface) return false;
  if (!footprint_.empty()) {
    if (!model::inside_polygon(footprint_, point.head<2>())) return false;
    // On an edge counts as outside: a sensor may sit flush on the body.
    for (std::size_t i = 0; i < footprint_.size(); ++i) {
      const model::Vec2& a = footprint_[i];
      const model::Vec2 e = footprint_[(i + 1) % footprint_.size()] - a;
      const double s = std::clamp((point.head<2>() - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
      if ((a + s * e - point.head<2>()).norm() <= kSurface) return false;
    }
    return true;
  }
  return point.head<2>().norm() < radius_ - kSurface;
}

// The farthest point along the ray at azimuth theta of the parts' horizontal projection.
double BodyOccluder::outline_radius(double theta) const {
  const model::Vec2 u(std::cos(theta), std::sin(theta));
  double farthest = 0.0;
  for (const model::BodyPart& part : *parts_) {
    if (!part.cylinder) continue;
    const model::Vec2& c = part.cylinder->centre;
    const double along = u.dot(c);
    const double square =
        part.cylinder->radius * part.cylinder->radius - (c.squaredNorm() - along * along);
    if (square >= 0) farthest = std::max(farthest, along + std::sqrt(square));
  }
  constexpr double kTwoPi = 2 * std::numbers::pi;
  const int bin = std::clamp(static_cast<int>(model::wrap_angle(theta) / (kTwoPi / kOutlineBins)),
                             0, kOutlineBins - 1);
  for (const Edge& edge : outline_bins_[static_cast<std::size_t>(bin)]) {
    double rho = 0.0;
    double along_edge = 0.0;
    if (!line_crossing(model::Vec2::Zero(), u, edge.a, edge.b - edge.a, rho, along_edge)) {
      // An edge along the ray: its end points lie on it when a is on the ray.
      if (std::abs(cross2(edge.a, u)) < 1e-12) {
        farthest = std::max({farthest, edge.a.dot(u), edge.b.dot(u)});
      }
      continue;
    }
    if (rho >= 0 && along_edge >= 0 && along_edge <= 1) farthest = std::max(farthest, rho);
  }
  return farthest;
}

double BodyOccluder::radius_at(double theta) const {
  if (parts_) return outline_radius(theta);
  if (footprint_.empty()) return radius_;
  const model::Vec2 far = model::Vec2(std::cos(theta), std::sin(theta)) * (2 * radius_ + 1.0);
  std::vector<double> crossings;
  edge_crossings(footprint_, model::Vec2::Zero(), far, crossings);
  if (crossings.empty()) return 0.0;
  return *std::max_element(crossings.begin(), crossings.end()) * far.norm();
}

}  // namespace rigdesign::geometry
