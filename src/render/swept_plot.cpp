// Swept coverage from above: when each cell around the robot is first seen while it turns or
// drives an arc, and which cells of the body's path are seen too late to stop for.
#include "rigdesign/render/swept_plot.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "cairo_canvas.hpp"
#include "chart_axes.hpp"
#include "coverage_chart_parts.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::render {
namespace {

constexpr Rgb kSweepNever{0.72, 0.72, 0.72};  // never seen within the horizon
constexpr double kSweepMargin = 70.0;         // [px] left of and below the map, for the axes
constexpr double kSweepTitle = 56.0;          // [px] above the map
constexpr double kSweepLegendWidth = 360.0;   // [px] right of the map
constexpr int kSweepPathSamples = 200;        // points of the centre's path

// Dark blue at t = 0 through teal to pale yellow at the horizon: early reads dark.
Rgb sweep_time_colour(double share) {
  share = std::clamp(share, 0.0, 1.0);
  const Rgb stops[] = {{0.13, 0.18, 0.5}, {0.15, 0.58, 0.58}, {0.96, 0.9, 0.45}};
  const int i = share < 0.5 ? 0 : 1;
  const double f = share < 0.5 ? share * 2 : share * 2 - 1;
  return {stops[i].r + f * (stops[i + 1].r - stops[i].r),
          stops[i].g + f * (stops[i + 1].g - stops[i].g),
          stops[i].b + f * (stops[i + 1].b - stops[i].b)};
}

// World (x forward, y left) to canvas: forward up, left to the left, equal scales.
struct SweepView {
  PlotArea area;
  double extent = 1.0;  // [m] half the map's width
  double scale() const { return (area.right - area.left) / (2 * extent); }
  double px(const model::Vec2& p) const { return 0.5 * (area.left + area.right) - p.y() * scale(); }
  double py(const model::Vec2& p) const { return 0.5 * (area.top + area.bottom) - p.x() * scale(); }
};

// Everything drawn fits: the grid's disc and the body wherever the path takes it.
SweepView sweep_view(const metrics::SweptCoverage& sweep, const metrics::SweepRun& run,
                     int map_size) {
  double body = 0.0;
  for (const model::Vec2& p : sweep.body_outline) body = std::max(body, p.norm());
  double extent = sweep.distance + sweep.cell / 2;
  for (int i = 0; i <= kSweepPathSamples; ++i) {
    const double t = sweep.horizon * i / kSweepPathSamples;
    extent = std::max(extent, run.motion.pose_at(t).position.norm() + body);
  }
  return {{kSweepMargin, kSweepTitle, kSweepMargin + map_size, kSweepTitle + map_size},
          extent * 1.04};
}

void draw_sweep_cells(cairo_t* cairo, const metrics::SweptCoverage& sweep,
                      const metrics::SweepRun& run, const SweepView& view) {
  const double side = sweep.cell * view.scale();
  // Edge-to-edge squares without antialiasing: blended edges would leave pale seams.
  cairo_set_antialias(cairo, CAIRO_ANTIALIAS_NONE);
  for (const metrics::SweepCell& cell : run.cells) {
    set_colour(cairo,
               cell.first_seen ? sweep_time_colour(*cell.first_seen / sweep.horizon) : kSweepNever);
    cairo_rectangle(cairo, view.px(cell.centre) - side / 2, view.py(cell.centre) - side / 2, side,
                    side);
    cairo_fill(cairo);
  }
  cairo_set_antialias(cairo, CAIRO_ANTIALIAS_DEFAULT);
  // The swept path dotted white (it shows on every colour of the scale), its late cells
  // framed, over the colours.
  for (const metrics::SweepCell& cell : run.cells) {
    if (!cell.reached) continue;
    set_colour(cairo, {1.0, 1.0, 1.0}, 0.85);
    cairo_arc(cairo, view.px(cell.centre), view.py(cell.centre), std::max(1.0, side * 0.12), 0,
              2 * std::numbers::pi);
    cairo_fill(cairo);
    if (!cell.late) continue;
    set_colour(cairo, kFailColour);
    cairo_set_line_width(cairo, std::clamp(side * 0.15, 1.0, 2.5));
    cairo_rectangle(cairo, view.px(cell.centre) - side / 2, view.py(cell.centre) - side / 2, side,
                    side);
    cairo_stroke(cairo);
  }
}

// The body at the start (filled) and at the horizon's end (dashed), each with a line from its
// centre forward, and the path its centre drives.
void draw_sweep_body(cairo_t* cairo, const metrics::SweptCoverage& sweep,
                     const metrics::SweepRun& run, const SweepView& view) {
  const auto outline = [&](const metrics::SweepPose& pose) {
    const Eigen::Rotation2Dd R_world_robot(pose.heading);
    for (std::size_t i = 0; i < sweep.body_outline.size(); ++i) {
      const model::Vec2 p = pose.position + R_world_robot * sweep.body_outline[i];
      i == 0 ? cairo_move_to(cairo, view.px(p), view.py(p))
             : cairo_line_to(cairo, view.px(p), view.py(p));
    }
    cairo_close_path(cairo);
    double radius = 0.0;
    for (const model::Vec2& p : sweep.body_outline) radius = std::max(radius, p.norm());
    const model::Vec2 nose = pose.position + R_world_robot * model::Vec2(radius, 0.0);
    cairo_move_to(cairo, view.px(pose.position), view.py(pose.position));
    cairo_line_to(cairo, view.px(nose), view.py(nose));
  };
  outline(run.motion.pose_at(0.0));
  set_colour(cairo, kBodyColour, 0.85);
  cairo_fill_preserve(cairo);
  set_colour(cairo, kInkColour);
  cairo_set_line_width(cairo, 1.5);
  cairo_stroke(cairo);
  const double dash[] = {6.0, 4.0};
  cairo_set_dash(cairo, dash, 2, 0);
  outline(run.motion.pose_at(sweep.horizon));
  cairo_stroke(cairo);
  cairo_set_dash(cairo, nullptr, 0, 0);
  if (run.motion.kind != metrics::SweepKind::arc) return;
  cairo_set_line_width(cairo, 2.0);
  for (int i = 0; i <= kSweepPathSamples; ++i) {
    const model::Vec2 p = run.motion.pose_at(sweep.horizon * i / kSweepPathSamples).position;
    i == 0 ? cairo_move_to(cairo, view.px(p), view.py(p))
           : cairo_line_to(cairo, view.px(p), view.py(p));
  }
  cairo_stroke(cairo);
}

// The map's frame with metres on marks outside it (grid lines would hide cells).
void draw_sweep_axes(cairo_t* cairo, const SweepView& view) {
  const PlotArea& area = view.area;
  set_colour(cairo, kInkColour);
  cairo_set_line_width(cairo, 1);
  cairo_rectangle(cairo, area.left, area.top, area.right - area.left, area.bottom - area.top);
  cairo_stroke(cairo);
  const std::vector<double> ticks =
      tick_values(-view.extent, view.extent, tick_step(2 * view.extent, 8, StepRounding::up));
  const Axis y_across{
      .ticks = ticks, .pixel = [&](double y) { return view.px(model::Vec2(0.0, y)); }, .digits = 3};
  const Axis x_up{
      .ticks = ticks, .pixel = [&](double x) { return view.py(model::Vec2(x, 0.0)); }, .digits = 3};
  draw_ticks(cairo, area, y_across, x_up, {.size = 11, .below = 17, .beside = 8, .lift = 4},
             TickLine::mark);
  draw_x_title(cairo, area, "y [m], left (robot frame at t = 0)", 38, 12);
  draw_y_title(cairo, area, "x [m], forward", 18, 12);
}

// The time scale as a bar with its ticks, top to bottom from 0 to the horizon.
double draw_sweep_time_bar(cairo_t* cairo, const metrics::SweptCoverage& sweep, double x,
                           double y) {
  set_colour(cairo, kInkColour);
  draw_text(cairo, "first seen [s]", x, y, 13, Anchor::left, true);
  constexpr double kBarHeight = 180.0, kBarWidth = 22.0;
  const double top = y + 12;
  for (int i = 0; i < 90; ++i) {
    set_colour(cairo, sweep_time_colour(i / 89.0));
    cairo_rectangle(cairo, x, top + kBarHeight * i / 90.0, kBarWidth, kBarHeight / 90.0 + 0.5);
    cairo_fill(cairo);
  }
  set_colour(cairo, kInkColour);
  for (const double t :
       tick_values(0.0, sweep.horizon, tick_step(sweep.horizon, 5, StepRounding::up))) {
    const double at = top + kBarHeight * t / sweep.horizon;
    cairo_move_to(cairo, x + kBarWidth, at);
    cairo_line_to(cairo, x + kBarWidth + 5, at);
    cairo_stroke(cairo);
    draw_text(cairo, model::format_number(t, 4), x + kBarWidth + 9, at + 4, 11);
  }
  return top + kBarHeight + 30;
}

void draw_sweep_legend(cairo_t* cairo, const metrics::SweptCoverage& sweep,
                       const metrics::SweepRun& run, const SweepView& view) {
  const double x = view.area.right + 24;
  double y = draw_sweep_time_bar(cairo, sweep, x, view.area.top + 14);
  legend_box(cairo, x, y, kSweepNever, "never seen within the horizon", 12);
  y += 22;
  set_colour(cairo, kFailColour);
  cairo_set_line_width(cairo, 2);
  cairo_rectangle(cairo, x + 8, y - 12, 13, 13);
  cairo_stroke(cairo);
  set_colour(cairo, kInkColour);
  draw_text(cairo, "late: seen < t_stop before the body", x + 38, y, 12);
  y += 22;
  set_colour(cairo, sweep_time_colour(0.0));
  cairo_rectangle(cairo, x + 8, y - 12, 13, 13);
  cairo_fill(cairo);
  set_colour(cairo, {1.0, 1.0, 1.0}, 0.85);
  cairo_arc(cairo, x + 14.5, y - 5.5, 3, 0, 2 * std::numbers::pi);
  cairo_fill(cairo);
  set_colour(cairo, kInkColour);
  draw_text(cairo, "in the body's swept path", x + 38, y, 12);
  y += 22;
  legend_box(cairo, x, y, kBodyColour, "body at t = 0", 12);
  y += 22;
  const auto line_entry = [&](bool dashed, const std::string& label) {
    const double dash[] = {6.0, 4.0};
    set_colour(cairo, kInkColour);
    cairo_set_line_width(cairo, dashed ? 1.5 : 2.0);
    cairo_set_dash(cairo, dash, dashed ? 2 : 0, 0);
    cairo_move_to(cairo, x, y - 5);
    cairo_line_to(cairo, x + 30, y - 5);
    cairo_stroke(cairo);
    cairo_set_dash(cairo, nullptr, 0, 0);
    draw_text(cairo, label, x + 38, y, 12);
    y += 22;
  };
  line_entry(true, "body at the horizon");
  if (run.motion.kind == metrics::SweepKind::arc) line_entry(false, "path of the centre");
  y += 10;
  const std::string lines[] = {
      "cell " + model::format_number(sweep.cell * 100, 3) +
          " cm, d = " + model::format_number(sweep.distance, 3) + " m",
      "horizon " + model::format_number(sweep.horizon, 3) + " s, time step " +
          model::format_number(sweep.time_step * 1000, 3) + " ms",
      "t_stop = " + model::format_number(sweep.stopping_time, 3) + " s",
      "seen: " + model::format_number(run.seen_share * 100, 4) + " % of the cells",
      "swept path: " + std::to_string(run.swept) + " cells, " + std::to_string(run.late) + " late"};
  for (const std::string& line : lines) {
    draw_text(cairo, line, x, y, 12);
    y += 18;
  }
}

}  // namespace

void plot_swept_coverage(const metrics::SweptCoverage& sweep, const metrics::SweepRun& run,
                         const std::string& title, const std::string& path, int map_size) {
  const SweepView view = sweep_view(sweep, run, map_size);
  const int width = static_cast<int>(kSweepMargin + map_size + kSweepLegendWidth);
  const int height = static_cast<int>(kSweepTitle + map_size + kSweepMargin);
  draw_to_file(path, width, height, [&](cairo_t* cairo) {
    set_colour(cairo, kInkColour);
    draw_text(cairo, title, width / 2.0, 32, 17, Anchor::centre, true);
    cairo_save(cairo);
    cairo_rectangle(cairo, view.area.left, view.area.top, map_size, map_size);
    cairo_clip(cairo);
    draw_sweep_cells(cairo, sweep, run, view);
    draw_sweep_body(cairo, sweep, run, view);
    cairo_restore(cairo);
    draw_sweep_axes(cairo, view);
    draw_sweep_legend(cairo, sweep, run, view);
  });
}

}  // namespace rigdesign::render
