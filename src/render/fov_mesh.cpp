#include "rigdesign/render/fov_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

namespace rigdesign::render {
namespace {

constexpr double kPi = std::numbers::pi;
// 48 segments over a full turn are 7.5 deg chords: round at figure sizes, and a spherical
// cap tessellated this finely loses well under 1 % of its volume.
constexpr int kSegmentsOnWiderAngle = 48;
// A segment count this close to a whole number is taken as it (datasheet angles converted from
// degrees land within ~1e-15 of a round share).
constexpr double kSegmentShareTolerance = 1e-9;

// A FOV's directions (model::FovShape::direction over its domain) sampled on a grid. The map
// is oriented so that (d/du) x (d/dv) points out through the far cap, which makes
// counter-clockwise grid quads outward-facing there.
struct AngleGrid {
  const model::FovShape* shape = nullptr;
  model::AngularDomain domain;
  int columns = 1;  // segments along u
  int rows = 1;     // segments along v

  double u(int i) const { return domain.u_min + (domain.u_max - domain.u_min) * i / columns; }
  double v(int j) const { return domain.v_min + (domain.v_max - domain.v_min) * j / rows; }
  bool wraps_u() const { return domain.wraps_u; }
  bool is_pole_row(int j) const {
    return (j == 0 && domain.pole_at_v_min) || (j == rows && domain.pole_at_v_max);
  }
  int vertices_in_row(int j) const {
    if (is_pole_row(j)) return 1;
    return wraps_u() ? columns : columns + 1;
  }
  model::Vec3 direction(int i, int j) const { return shape->direction(u(i), v(j)); }
};

// [rad] the visible volume's grid: fine enough that a cut by the body (a top plate shadowing
// beams a few degrees down) falls within a couple of degrees of where the coverage engine has it.
constexpr double kVisibleMeshStep = 2.0 * kPi / 180.0;

// How far along `direction` the sensor sees before the body, up to `reach` [m]. The open
// segment from the origin passes through the body for every length beyond the first hit, so
// bisection on BodyOccluder::blocks finds it (to 2^-30 of the reach).
double visible_reach(const geometry::BodyOccluder& body, const model::Vec3& origin,
                     const model::Vec3& direction, double reach) {
  if (!body.blocks(origin, origin + direction * reach)) return reach;
  double clear = 0.0, blocked = reach;
  for (int i = 0; i < 30; ++i) {
    const double middle = 0.5 * (clear + blocked);
    (body.blocks(origin, origin + direction * middle) ? blocked : clear) = middle;
  }
  return clear;
}

int segments_for(double span, double wider_span) {
  const double share = span / wider_span;
  return std::max(
      1, static_cast<int>(std::ceil(kSegmentsOnWiderAngle * share - kSegmentShareTolerance)));
}

AngleGrid angle_grid(const model::FieldOfView& fov, double max_step) {
  AngleGrid grid;
  grid.shape = &fov.shape();
  grid.domain = fov.shape().domain();
  const double u_span = grid.domain.u_max - grid.domain.u_min;
  const double v_span = grid.domain.v_max - grid.domain.v_min;
  const double wider_span = std::max(u_span, v_span);
  if (wider_span > 0) {
    grid.columns = segments_for(u_span, wider_span);
    grid.rows = segments_for(v_span, wider_span);
  }
  if (max_step > 0) {
    grid.columns = std::max(grid.columns, static_cast<int>(std::ceil(u_span / max_step)));
    grid.rows = std::max(grid.rows, static_cast<int>(std::ceil(v_span / max_step)));
  }
  return grid;
}

// Builds the closed shell between two spheres cut by the FOV: the far cap, the near cap (or
// the sensor origin as an apex when the near radius is 0) and the walls along the grid's
// boundary. Pole rows and a wrapping column share vertices, and triangles that collapse on
// them are dropped, so the surface is closed and every edge is used once each way.
class ShellBuilder {
 public:
  ShellBuilder(const AngleGrid& grid, const model::Pose3& T_robot_sensor)
      : grid_(grid), T_robot_sensor_(T_robot_sensor) {}

  model::TriangleMesh build(double near_radius, double far_radius) {
    const Layer outer = add_layer(far_radius);
    const Layer inner = add_layer(near_radius);
    add_caps(outer, inner);
    add_wall(outer, inner, 0, 0, 1, 0, grid_.columns);                        // v = v_min
    add_wall(outer, inner, grid_.columns, grid_.rows, -1, 0, grid_.columns);  // v = v_max
    if (!grid_.wraps_u()) {
      add_wall(outer, inner, grid_.columns, 0, 0, 1, grid_.rows);  // u = u_max
      add_wall(outer, inner, 0, grid_.rows, 0, -1, grid_.rows);    // u = u_min
    }
    return std::move(mesh_);
  }

 private:
  // One sphere's vertices, row by row; a layer of radius 0 is the single apex vertex.
  struct Layer {
    int first = 0;
    bool is_apex = false;
  };

  Layer add_layer(double radius) {
    const Layer layer{static_cast<int>(mesh_.vertices.size()), radius <= 0.0};
    if (layer.is_apex) {
      mesh_.vertices.push_back(T_robot_sensor_.translation());
      return layer;
    }
    for (int j = 0; j <= grid_.rows; ++j) {
      for (int i = 0; i < grid_.vertices_in_row(j); ++i) {
        const model::Vec3 q_sensor = radius * grid_.direction(i, j);
        mesh_.vertices.push_back(T_robot_sensor_ * q_sensor);
      }
    }
    return layer;
  }

  int index(const Layer& layer, int i, int j) const {
    if (layer.is_apex) return layer.first;
    int row_start = layer.first;
    for (int row = 0; row < j; ++row) row_start += grid_.vertices_in_row(row);
    if (grid_.is_pole_row(j)) return row_start;
    return row_start + (grid_.wraps_u() ? i % grid_.columns : i);
  }

  void add_triangle(int a, int b, int c) {
    if (a == b || b == c || c == a) return;  // collapsed on a pole or the apex
    mesh_.triangles.push_back({a, b, c});
  }

  // Two triangles a-b-c and a-c-d of a quad given counter-clockwise seen from outside.
  void add_quad(int a, int b, int c, int d) {
    add_triangle(a, b, c);
    add_triangle(a, c, d);
  }

  void add_caps(const Layer& outer, const Layer& inner) {
    for (int j = 0; j < grid_.rows; ++j) {
      for (int i = 0; i < grid_.columns; ++i) {
        add_quad(index(outer, i, j), index(outer, i + 1, j), index(outer, i + 1, j + 1),
                 index(outer, i, j + 1));
        // The near cap faces the sensor, so its quads run the other way round.
        add_quad(index(inner, i, j), index(inner, i, j + 1), index(inner, i + 1, j + 1),
                 index(inner, i + 1, j));
      }
    }
  }

  // Walls along one side of the grid, walked counter-clockwise in (u, v) from (i0, j0) in
  // `steps` steps of (di, dj). The far cap runs each boundary edge p -> q, so the wall runs it
  // q -> p to face outward too.
  void add_wall(const Layer& outer, const Layer& inner, int i0, int j0, int di, int dj, int steps) {
    for (int s = 0; s < steps; ++s) {
      const int pi = i0 + s * di;
      const int pj = j0 + s * dj;
      const int qi = pi + di;
      const int qj = pj + dj;
      add_quad(index(outer, qi, qj), index(outer, pi, pj), index(inner, pi, pj),
               index(inner, qi, qj));
    }
  }

  AngleGrid grid_;
  model::Pose3 T_robot_sensor_;
  model::TriangleMesh mesh_;
};

}  // namespace

model::TriangleMesh fov_mesh(const model::SensorMode& mode, const model::Pose3& T_robot_sensor,
                             double truncate_at) {
  const double near_radius = std::max(0.0, mode.min_range);
  const double far_radius = std::min(mode.max_range, truncate_at);
  if (!(far_radius > near_radius)) return {};
  const AngleGrid grid = angle_grid(mode.fov, 0.0);
  return ShellBuilder(grid, T_robot_sensor).build(near_radius, far_radius);
}

model::TriangleMesh visible_fov_mesh(const model::SensorMode& mode,
                                     const model::Pose3& T_robot_sensor, double truncate_at,
                                     const geometry::BodyOccluder& body) {
  const double near_radius = std::max(0.0, mode.min_range);
  const double far_radius = std::min(mode.max_range, truncate_at);
  if (!(far_radius > near_radius)) return {};
  const AngleGrid grid = angle_grid(mode.fov, kVisibleMeshStep);
  model::TriangleMesh mesh = ShellBuilder(grid, T_robot_sensor).build(near_radius, far_radius);
  const model::Vec3 origin = T_robot_sensor.translation();
  for (model::Vec3& vertex : mesh.vertices) {
    const double reach = (vertex - origin).norm();
    if (reach <= 0.0) continue;
    const model::Vec3 direction = (vertex - origin) / reach;
    vertex = origin + direction * visible_reach(body, origin, direction, reach);
  }
  return mesh;
}

}  // namespace rigdesign::render
