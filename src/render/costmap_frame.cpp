#include "rigdesign/render/costmap_frame.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cairo_canvas.hpp"
#include "rigdesign/costmap/cost_values.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::render {
namespace {

using render::Anchor;
using render::draw_text;
using render::draw_to_file;
using render::set_colour;

constexpr int kTitleHeight = 28;        // [px]
constexpr int kFrameAxisMargin = 48;    // [px] left of the map: y tick labels
constexpr int kFrameBottomMargin = 40;  // [px] below the map: x tick labels
constexpr int kFrameLegendWidth = 290;  // [px] right of the map
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

// Map axes in world metres, a scale bar, and the legend: what each colour and line means and
// which sensor each wedge belongs to.
void draw_frame_furniture(cairo_t* cairo, const CostmapFrame& frame,
                          const costmap::GridWindow& window, double pixels_per_metre, int map_width,
                          int map_height) {
  const double left = kFrameAxisMargin, top = kTitleHeight;
  const double right = left + map_width, bottom = top + map_height;
  const model::Vec2 origin = window.origin();
  set_colour(cairo, kInkColour);
  cairo_set_line_width(cairo, 1);
  cairo_rectangle(cairo, left, top, map_width, map_height);
  cairo_stroke(cairo);
  // Ticks every whole metre (every 2 m on a wide map).
  const double step = map_width / pixels_per_metre > 12 ? 2.0 : 1.0;
  for (double x = std::ceil(origin.x() / step) * step;
       (x - origin.x()) * pixels_per_metre <= map_width; x += step) {
    const double at = left + (x - origin.x()) * pixels_per_metre;
    cairo_move_to(cairo, at, bottom);
    cairo_line_to(cairo, at, bottom + 5);
    cairo_stroke(cairo);
    draw_text(cairo, model::format_number(x, 3), at, bottom + 17, 11, Anchor::centre);
  }
  for (double y = std::ceil(origin.y() / step) * step;
       (y - origin.y()) * pixels_per_metre <= map_height; y += step) {
    const double at = bottom - (y - origin.y()) * pixels_per_metre;
    cairo_move_to(cairo, left - 5, at);
    cairo_line_to(cairo, left, at);
    cairo_stroke(cairo);
    draw_text(cairo, model::format_number(y, 3), left - 8, at + 4, 11, Anchor::right);
  }
  draw_text(cairo, "x [m] (world)", (left + right) / 2, bottom + 33, 12, Anchor::centre);
  cairo_save(cairo);
  cairo_translate(cairo, 12, (top + bottom) / 2);
  cairo_rotate(cairo, -std::numbers::pi / 2);
  draw_text(cairo, "y [m]", 0, 0, 12, Anchor::centre);
  cairo_restore(cairo);
  draw_text(cairo, frame.title, 6, 19, 13, Anchor::left, true);

  // Scale bar inside the map, bottom left, on a white patch.
  const double bar = 1.0 * pixels_per_metre;
  cairo_set_source_rgba(cairo, 1, 1, 1, 0.85);
  cairo_rectangle(cairo, left + 6, bottom - 30, bar + 20, 26);
  cairo_fill(cairo);
  set_colour(cairo, kInkColour);
  cairo_set_line_width(cairo, 3);
  cairo_move_to(cairo, left + 16, bottom - 10);
  cairo_line_to(cairo, left + 16 + bar, bottom - 10);
  cairo_stroke(cairo);
  draw_text(cairo, "1 m", left + 16 + bar / 2, bottom - 15, 11, Anchor::centre, true);

  double x = right + 16, y = top + 14;
  const auto swatch = [&](const Rgb& colour, const std::string& text) {
    set_colour(cairo, colour);
    cairo_rectangle(cairo, x, y - 11, 22, 13);
    cairo_fill_preserve(cairo);
    set_colour(cairo, kInkColour, 0.5);
    cairo_set_line_width(cairo, 0.8);
    cairo_stroke(cairo);
    set_colour(cairo, kInkColour);
    draw_text(cairo, text, x + 30, y, 12);
    y += 19;
  };
  const auto line = [&](const Rgb& colour, double line_width, const std::string& text) {
    set_colour(cairo, colour);
    cairo_set_line_width(cairo, line_width);
    cairo_move_to(cairo, x, y - 5);
    cairo_line_to(cairo, x + 22, y - 5);
    cairo_stroke(cairo);
    set_colour(cairo, kInkColour);
    draw_text(cairo, text, x + 30, y, 12);
    y += 19;
  };
  set_colour(cairo, kInkColour);
  draw_text(cairo, "master grid cost (nav2 values)", x, y, 12, Anchor::left, true);
  y += 19;
  swatch(colour_of(costmap::cost::kLethal), "254 lethal: obstacle");
  swatch(colour_of(costmap::cost::kInscribed), "253 inscribed: body would touch");
  swatch(inflated(200), "1-252 inflated (pale: low)");
  swatch(colour_of(costmap::cost::kFree), "0 free");
  swatch(colour_of(costmap::cost::kUnknown), "255 unknown");
  swatch(kRemembered, "kept by the Hit Layer only");
  y += 8;
  line(kPath, 2.5, "planned path");
  line(kTrail, 2.0, "driven trail");
  line(kInkColour, 1.0, "ground truth (body's height band)");
  swatch(frame.collided ? kCollision : kBodyColour, frame.collided ? "robot: COLLISION" : "robot");
  y += 8;
  set_colour(cairo, kInkColour);
  draw_text(cairo, "sensors (horizontal view, to range)", x, y, 12, Anchor::left, true);
  y += 19;
  for (const FovWedge& fov : frame.fovs) {
    set_colour(cairo, sensor_colour(fov.colour), 0.45);
    cairo_rectangle(cairo, x, y - 11, 22, 13);
    cairo_fill(cairo);
    set_colour(cairo, kInkColour);
    draw_text(cairo, fov.label, x + 30, y, 12);
    y += 19;
  }
}

}  // namespace

void draw_costmap_frame(const CostmapFrame& frame, const std::string& path, int pixels_per_cell) {
  const costmap::CostGrid& grid = *frame.master;
  const costmap::GridWindow& window = grid.window();
  const int scale = std::max(1, pixels_per_cell);
  const int map_width = window.width * scale;
  const int map_height = window.height * scale;
  const int legend_height = 300 + 20 * static_cast<int>(frame.fovs.size());
  const int width = kFrameAxisMargin + map_width + kFrameLegendWidth;
  const int height = kTitleHeight + std::max(map_height + kFrameBottomMargin, legend_height);
  const double pixels_per_metre = scale / window.resolution;
  const model::Vec2 origin = window.origin();
  // World metres to canvas pixels: x right, y up (the grid's top row is its largest y).
  const auto px = [&](const model::Vec2& p) {
    return model::Vec2(kFrameAxisMargin + (p.x() - origin.x()) * pixels_per_metre,
                       kTitleHeight + map_height - (p.y() - origin.y()) * pixels_per_metre);
  };
  draw_to_file(path, width, height, [&](cairo_t* cairo) {
    for (int y = 0; y < window.height; ++y) {
      for (int x = 0; x < window.width; ++x) {
        const bool remembered = !frame.remembered.empty() && frame.remembered[window.index(x, y)];
        set_colour(cairo, remembered ? kRemembered : colour_of(grid.at(x, y)));
        cairo_rectangle(cairo, kFrameAxisMargin + x * scale,
                        kTitleHeight + (window.height - 1 - y) * scale, scale, scale);
        cairo_fill(cairo);
      }
    }
    // Wedges, outlines and lines stay on the map.
    cairo_save(cairo);
    cairo_rectangle(cairo, kFrameAxisMargin, kTitleHeight, map_width, map_height);
    cairo_clip(cairo);
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
    cairo_restore(cairo);
    draw_frame_furniture(cairo, frame, window, pixels_per_metre, map_width, map_height);
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
    wedge.half_angle = mode.fov.horizontal() / 2;
    wedge.range = std::min(mode.max_range, marking_ranges[i]);
    wedge.colour = i;
    wedge.label = mount.id + ": " + mount.sensor_id;
    wedges.push_back(wedge);
  }
  return wedges;
}

}  // namespace rigdesign::render
