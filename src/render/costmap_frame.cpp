#include "rigdesign/render/costmap_frame.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cairo_canvas.hpp"
#include "chart_axes.hpp"
#include "rigdesign/costmap/cost_values.hpp"

namespace rigdesign::render {
namespace {

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

// The map on the canvas: world metres to pixels, x right, y up (the grid's top row is its
// largest y).
struct MapView {
  const costmap::GridWindow& window;
  int scale;  // [px] per cell
  int map_width, map_height;
  double pixels_per_metre;
  PlotArea area() const {
    return {kFrameAxisMargin, kTitleHeight, kFrameAxisMargin + static_cast<double>(map_width),
            kTitleHeight + static_cast<double>(map_height)};
  }
  model::Vec2 px(const model::Vec2& p) const {
    const model::Vec2 origin = window.origin();
    return model::Vec2(kFrameAxisMargin + (p.x() - origin.x()) * pixels_per_metre,
                       kTitleHeight + map_height - (p.y() - origin.y()) * pixels_per_metre);
  }
};

void draw_cells(cairo_t* cairo, const CostmapFrame& frame, const MapView& view) {
  const costmap::GridWindow& window = view.window;
  for (int y = 0; y < window.height; ++y) {
    for (int x = 0; x < window.width; ++x) {
      const bool remembered = !frame.remembered.empty() && frame.remembered[window.index(x, y)];
      set_colour(cairo, remembered ? kRemembered : colour_of(frame.master->at(x, y)));
      cairo_rectangle(cairo, kFrameAxisMargin + x * view.scale,
                      kTitleHeight + (window.height - 1 - y) * view.scale, view.scale, view.scale);
      cairo_fill(cairo);
    }
  }
}

void draw_wedges(cairo_t* cairo, const CostmapFrame& frame, const MapView& view) {
  for (const FovWedge& fov : frame.fovs) {
    const model::Vec2 apex = view.px(fov.apex);
    const double radius = fov.range * view.pixels_per_metre;
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
}

// The ground truth's outlines, the driven trail under the planned path, and the robot with a
// line to its nose.
void draw_outlines_and_robot(cairo_t* cairo, const CostmapFrame& frame, const MapView& view) {
  cairo_set_line_width(cairo, 1.0);
  set_colour(cairo, kInkColour, 0.8);
  for (const std::vector<model::Vec2>& outline : frame.obstacles) {
    if (outline.empty()) continue;
    const model::Vec2 first = view.px(outline.front());
    cairo_move_to(cairo, first.x(), first.y());
    for (const model::Vec2& p : outline) cairo_line_to(cairo, view.px(p).x(), view.px(p).y());
    cairo_close_path(cairo);
    cairo_stroke(cairo);
  }
  const auto polyline = [&](const std::vector<model::Vec2>& points, const Rgb& colour,
                            double line_width) {
    if (points.size() < 2) return;
    set_colour(cairo, colour);
    cairo_set_line_width(cairo, line_width);
    cairo_move_to(cairo, view.px(points.front()).x(), view.px(points.front()).y());
    for (const model::Vec2& p : points) cairo_line_to(cairo, view.px(p).x(), view.px(p).y());
    cairo_stroke(cairo);
  };
  polyline(frame.trail, kTrail, 2.0);
  polyline(frame.path, kPath, 2.5);
  const model::Vec2 robot = view.px(frame.robot);
  set_colour(cairo, frame.collided ? kCollision : kBodyColour, 0.55);
  if (frame.footprint.empty()) {
    cairo_arc(cairo, robot.x(), robot.y(), frame.robot_radius * view.pixels_per_metre, 0,
              2 * std::numbers::pi);
  } else {
    // The outline turned by the robot's yaw and moved to its position.
    const Eigen::Rotation2Dd turn(frame.yaw);
    for (std::size_t i = 0; i < frame.footprint.size(); ++i) {
      const model::Vec2 corner = view.px(frame.robot + turn * frame.footprint[i]);
      if (i == 0) {
        cairo_move_to(cairo, corner.x(), corner.y());
      } else {
        cairo_line_to(cairo, corner.x(), corner.y());
      }
    }
    cairo_close_path(cairo);
  }
  cairo_fill_preserve(cairo);
  set_colour(cairo, kInkColour);
  cairo_set_line_width(cairo, 1.5);
  cairo_stroke(cairo);
  if (!frame.footprint.empty()) {
    // The circumscribed cylinder the collision check uses, thin.
    cairo_set_line_width(cairo, 0.75);
    cairo_arc(cairo, robot.x(), robot.y(), frame.robot_radius * view.pixels_per_metre, 0,
              2 * std::numbers::pi);
    cairo_stroke(cairo);
  }
  const model::Vec2 nose = view.px(
      frame.robot + frame.robot_radius * model::Vec2(std::cos(frame.yaw), std::sin(frame.yaw)));
  cairo_move_to(cairo, robot.x(), robot.y());
  cairo_line_to(cairo, nose.x(), nose.y());
  cairo_stroke(cairo);
}

// The map's frame with world metres on marks outside it (grid lines would hide cells):
// every whole metre, every 2 m on a wide map.
void draw_map_axes(cairo_t* cairo, const MapView& view) {
  const PlotArea area = view.area();
  const model::Vec2 origin = view.window.origin();
  set_colour(cairo, kInkColour);
  cairo_set_line_width(cairo, 1);
  cairo_rectangle(cairo, area.left, area.top, view.map_width, view.map_height);
  cairo_stroke(cairo);
  const double ppm = view.pixels_per_metre;
  const double step = view.map_width / ppm > 12 ? 2.0 : 1.0;
  const Axis x{.ticks = tick_values(origin.x(), origin.x() + view.map_width / ppm, step),
               .pixel = [&](double value) { return area.left + (value - origin.x()) * ppm; },
               .digits = 3};
  const Axis y{.ticks = tick_values(origin.y(), origin.y() + view.map_height / ppm, step),
               .pixel = [&](double value) { return area.bottom - (value - origin.y()) * ppm; },
               .digits = 3};
  draw_ticks(cairo, area, x, y, {.size = 11, .below = 17, .beside = 8, .lift = 4}, TickLine::mark);
  draw_x_title(cairo, area, "x [m] (world)", 33, 12);
  draw_y_title(cairo, area, "y [m]", 12, 12);
}

// A 1 m scale bar inside the map, bottom left, on a white patch.
void draw_map_scale_bar(cairo_t* cairo, const MapView& view) {
  const PlotArea area = view.area();
  const double bar = 1.0 * view.pixels_per_metre;
  cairo_set_source_rgba(cairo, 1, 1, 1, 0.85);
  cairo_rectangle(cairo, area.left + 6, area.bottom - 30, bar + 20, 26);
  cairo_fill(cairo);
  set_colour(cairo, kInkColour);
  cairo_set_line_width(cairo, 3);
  cairo_move_to(cairo, area.left + 16, area.bottom - 10);
  cairo_line_to(cairo, area.left + 16 + bar, area.bottom - 10);
  cairo_stroke(cairo);
  draw_text(cairo, "1 m", area.left + 16 + bar / 2, area.bottom - 15, 11, Anchor::centre, true);
}

// Right of the map: what each colour and line means and which sensor each wedge belongs to.
void draw_costmap_legend(cairo_t* cairo, const CostmapFrame& frame, const PlotArea& area) {
  double x = area.right + 16, y = area.top + 14;
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
  const auto heading = [&](const std::string& text) {
    set_colour(cairo, kInkColour);
    draw_text(cairo, text, x, y, 12, Anchor::left, true);
    y += 19;
  };
  heading("master grid cost (nav2 values)");
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
  heading("sensors (horizontal view, to range)");
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
  const costmap::GridWindow& window = frame.master->window();
  const int scale = std::max(1, pixels_per_cell);
  const MapView view{window, scale, window.width * scale, window.height * scale,
                     scale / window.resolution};
  const int legend_height = 300 + 20 * static_cast<int>(frame.fovs.size());
  const int width = kFrameAxisMargin + view.map_width + kFrameLegendWidth;
  const int height = kTitleHeight + std::max(view.map_height + kFrameBottomMargin, legend_height);
  draw_to_file(path, width, height, [&](cairo_t* cairo) {
    draw_cells(cairo, frame, view);
    // Wedges, outlines and lines stay on the map.
    cairo_save(cairo);
    cairo_rectangle(cairo, kFrameAxisMargin, kTitleHeight, view.map_width, view.map_height);
    cairo_clip(cairo);
    draw_wedges(cairo, frame, view);
    draw_outlines_and_robot(cairo, frame, view);
    cairo_restore(cairo);
    draw_map_axes(cairo, view);
    set_colour(cairo, kInkColour);
    draw_text(cairo, frame.title, 6, 19, 13, Anchor::left, true);
    draw_map_scale_bar(cairo, view);
    draw_costmap_legend(cairo, frame, view.area());
  });
}

}  // namespace rigdesign::render
