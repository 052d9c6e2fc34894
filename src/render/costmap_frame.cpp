#include "rigdesign/render/costmap_frame.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cairo_canvas.hpp"
#include "rigdesign/costmap/cost_values.hpp"

namespace rigdesign::render {
namespace {

using render::draw_text;
using render::draw_to_file;
using render::set_colour;

constexpr int kTitleHeight = 28;  // [px]
constexpr Rgb kUnknown{0.78, 0.80, 0.86};
constexpr Rgb kLethal{0.05, 0.05, 0.05};
constexpr Rgb kInscribed{0.35, 0.10, 0.45};
constexpr Rgb kRemembered{0.95, 0.45, 0.05};
constexpr Rgb kPath{0.10, 0.55, 0.15};
constexpr Rgb kTrail{0.20, 0.35, 0.85};
constexpr Rgb kCollision{0.90, 0.10, 0.10};

// Inflated costs from pale yellow (1) to red (252).
Rgb inflated(std::uint8_t cost) {
  const double share = (cost - 1.0) / 251.0;
  return {1.0, 0.95 - 0.75 * share, 0.70 - 0.60 * share};
}

Rgb colour_of(std::uint8_t cost) {
  if (cost == costmap::cost::kFree) return {1.0, 1.0, 1.0};
  if (cost == costmap::cost::kUnknown) return kUnknown;
  if (cost == costmap::cost::kLethal) return kLethal;
  if (cost == costmap::cost::kInscribed) return kInscribed;
  return inflated(cost);
}

}  // namespace

void draw_costmap_frame(const CostmapFrame& frame, const std::string& path, int pixels_per_cell) {
  const costmap::CostGrid& grid = *frame.master;
  const costmap::GridWindow& window = grid.window();
  const int scale = std::max(1, pixels_per_cell);
  const int width = window.width * scale;
  const int height = window.height * scale + kTitleHeight;
  const double pixels_per_metre = scale / window.resolution;
  const model::Vec2 origin = window.origin();
  // World metres to canvas pixels: x right, y up (the grid's top row is its largest y).
  const auto px = [&](const model::Vec2& p) {
    return model::Vec2(
        (p.x() - origin.x()) * pixels_per_metre,
        kTitleHeight + window.height * scale - (p.y() - origin.y()) * pixels_per_metre);
  };
  draw_to_file(path, width, height, [&](cairo_t* cairo) {
    for (int y = 0; y < window.height; ++y) {
      for (int x = 0; x < window.width; ++x) {
        const bool remembered = !frame.remembered.empty() && frame.remembered[window.index(x, y)];
        set_colour(cairo, remembered ? kRemembered : colour_of(grid.at(x, y)));
        cairo_rectangle(cairo, x * scale, kTitleHeight + (window.height - 1 - y) * scale, scale,
                        scale);
        cairo_fill(cairo);
      }
    }
    for (const FovWedge& fov : frame.fovs) {
      const model::Vec2 apex = px(fov.apex);
      const double radius = fov.range * pixels_per_metre;
      set_colour(cairo, sensor_colour(fov.colour), 0.15);
      if (fov.half_angle >= std::numbers::pi) {
        cairo_arc(cairo, apex.x(), apex.y(), radius, 0, 2 * std::numbers::pi);
      } else {
        // Canvas angles run clockwise (y down), so world angles change sign.
        cairo_move_to(cairo, apex.x(), apex.y());
        cairo_arc(cairo, apex.x(), apex.y(), radius, -(fov.yaw + fov.half_angle),
                  -(fov.yaw - fov.half_angle));
        cairo_close_path(cairo);
      }
      cairo_fill(cairo);
    }
    cairo_set_line_width(cairo, 1.0);
    set_colour(cairo, kInkColour, 0.8);
    for (const std::vector<model::Vec2>& outline : frame.obstacles) {
      if (outline.empty()) continue;
      const model::Vec2 first = px(outline.front());
      cairo_move_to(cairo, first.x(), first.y());
      for (const model::Vec2& p : outline) cairo_line_to(cairo, px(p).x(), px(p).y());
      cairo_close_path(cairo);
      cairo_stroke(cairo);
    }
    const auto polyline = [&](const std::vector<model::Vec2>& points, const Rgb& colour,
                              double line_width) {
      if (points.size() < 2) return;
      set_colour(cairo, colour);
      cairo_set_line_width(cairo, line_width);
      cairo_move_to(cairo, px(points.front()).x(), px(points.front()).y());
      for (const model::Vec2& p : points) cairo_line_to(cairo, px(p).x(), px(p).y());
      cairo_stroke(cairo);
    };
    polyline(frame.trail, kTrail, 2.0);
    polyline(frame.path, kPath, 2.5);
    const model::Vec2 robot = px(frame.robot);
    set_colour(cairo, frame.collided ? kCollision : kBodyColour, 0.55);
    cairo_arc(cairo, robot.x(), robot.y(), frame.robot_radius * pixels_per_metre, 0,
              2 * std::numbers::pi);
    cairo_fill_preserve(cairo);
    set_colour(cairo, kInkColour);
    cairo_set_line_width(cairo, 1.5);
    cairo_stroke(cairo);
    const model::Vec2 nose = px(
        frame.robot + frame.robot_radius * model::Vec2(std::cos(frame.yaw), std::sin(frame.yaw)));
    cairo_move_to(cairo, robot.x(), robot.y());
    cairo_line_to(cairo, nose.x(), nose.y());
    cairo_stroke(cairo);
    set_colour(cairo, kInkColour);
    draw_text(cairo, frame.title, 6, 19, 13);
  });
}

std::vector<FovWedge> fov_wedges(const model::Rig& rig, const model::SensorLibrary& library,
                                 const costmap::Pose2& pose,
                                 std::span<const double> marking_ranges) {
  std::vector<FovWedge> wedges;
  const Eigen::Rotation2Dd R_world_robot(pose.yaw);
  for (std::size_t i = 0; i < rig.mounts.size(); ++i) {
    const model::Mount& mount = rig.mounts[i];
    const model::SensorMode& mode = *library.find(mount.sensor_id)->find_mode(mount.mode_id);
    const model::Vec3 axis = mount.T_robot_sensor.linear().col(0);
    const model::Vec2 offset = mount.T_robot_sensor.translation().head<2>();
    FovWedge wedge;
    wedge.apex = pose.position + R_world_robot * offset;
    wedge.yaw = pose.yaw + std::atan2(axis.y(), axis.x());
    wedge.half_angle = mode.fov.horizontal / 2;
    wedge.range = std::min(mode.max_range, marking_ranges[i]);
    wedge.colour = i;
    wedges.push_back(wedge);
  }
  return wedges;
}

}  // namespace rigdesign::render
