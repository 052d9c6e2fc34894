#include "rigdesign/render/localize_plot.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cairo_canvas.hpp"
#include "chart_axes.hpp"
#include "localize_markers.hpp"
#include "localize_view.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::render {
namespace {

constexpr Rgb kWall{0.3, 0.3, 0.3};
constexpr Rgb kUnheard{0.62, 0.62, 0.62};  // scans below the receiver's floor
constexpr Rgb kRegion{0.95, 0.6, 0.2};     // a credible region, under the markers

// Blue (low) through cyan and yellow to red (high).
Rgb ramp(double share) {
  share = std::clamp(share, 0.0, 1.0);
  const Rgb stops[] = {{0.2, 0.3, 0.85}, {0.1, 0.75, 0.85}, {0.95, 0.85, 0.15}, {0.85, 0.15, 0.1}};
  const double scaled = share * 3.0;
  const int i = std::min(2, static_cast<int>(scaled));
  const double f = scaled - i;
  return {stops[i].r + f * (stops[i + 1].r - stops[i].r),
          stops[i].g + f * (stops[i + 1].g - stops[i].g),
          stops[i].b + f * (stops[i + 1].b - stops[i].b)};
}

// The path's values as the colour ramp spans them; NaN is a scan that heard nothing.
struct ValueRange {
  double lowest = 0.0, highest = 1.0;
  bool any_value = false, any_unheard = false;
  double share(double value) const { return (value - lowest) / (highest - lowest); }
};

ValueRange value_range(const std::vector<double>& values) {
  ValueRange range;
  for (const double v : values) {
    if (std::isnan(v)) {
      range.any_unheard = true;
      continue;
    }
    range.lowest = range.any_value ? std::min(range.lowest, v) : v;
    range.highest = range.any_value ? std::max(range.highest, v) : v;
    range.any_value = true;
  }
  range.highest = std::max(range.lowest + 1e-9, range.highest);
  return range;
}

// A grid every 1, 2, 5 or 10 ... m, about 8 lines across, over the whole plot area.
void draw_localize_axes(cairo_t* cairo, const LocalizeView& view) {
  const PlotArea& a = view.area;
  const double half_height = view.span * (a.bottom - a.top) / (a.right - a.left) / 2;
  const double step = tick_step(view.span, 8, StepRounding::up);
  const double x_low = view.centre.x() - view.span / 2, x_high = view.centre.x() + view.span / 2;
  const double y_low = view.centre.y() - half_height, y_high = view.centre.y() + half_height;
  const Axis x{.ticks = tick_values(x_low, x_high, step),
               .pixel = [&](double value) { return view.px(model::Vec2(value, 0)).x(); },
               .digits = 6};
  const Axis y{.ticks = tick_values(y_low, y_high, step),
               .pixel = [&](double value) { return view.px(model::Vec2(0, value)).y(); },
               .digits = 6};
  draw_ticks(cairo, a, x, y, {.size = 12, .below = 18, .beside = 6, .lift = 4});
  draw_x_title(cairo, a, "x [m]", 36, 13);
  draw_text(cairo, "y [m]", 20, a.top - 10, 13, Anchor::left);
}

void draw_region(cairo_t* cairo, const LocalizePlot& plot, const LocalizeView& view) {
  set_colour(cairo, kRegion, 0.35);
  for (const model::Vec2& c : plot.region_cells) {
    const model::Vec2 corner = view.px(c - model::Vec2::Constant(plot.region_cell / 2));
    const model::Vec2 opposite = view.px(c + model::Vec2::Constant(plot.region_cell / 2));
    cairo_rectangle(cairo, corner.x(), opposite.y(), opposite.x() - corner.x(),
                    corner.y() - opposite.y());
  }
  cairo_fill(cairo);
}

void draw_walls(cairo_t* cairo, const LocalizePlot& plot, const LocalizeView& view) {
  set_colour(cairo, kWall);
  cairo_set_line_width(cairo, 4);
  for (const auto& [a, b] : plot.walls) {
    cairo_move_to(cairo, view.px(a).x(), view.px(a).y());
    cairo_line_to(cairo, view.px(b).x(), view.px(b).y());
    cairo_stroke(cairo);
  }
}

// Each reading as a dot in its value's colour (ink when the path has no values), a scan that
// heard nothing as a grey ring.
void draw_path(cairo_t* cairo, const LocalizePlot& plot, const LocalizeView& view,
               const ValueRange& range) {
  const bool valued = plot.values.size() == plot.path.size();
  for (std::size_t i = 0; i < plot.path.size(); ++i) {
    const model::Vec2 p = view.px(plot.path[i].head<2>());
    if (valued && std::isnan(plot.values[i])) {
      set_colour(cairo, kUnheard, 0.8);
      cairo_set_line_width(cairo, 1);
      cairo_new_sub_path(cairo);
      cairo_arc(cairo, p.x(), p.y(), 2.0, 0, 2 * std::numbers::pi);
      cairo_stroke(cairo);
      continue;
    }
    set_colour(cairo, valued ? ramp(range.share(plot.values[i])) : kInkColour, 0.8);
    cairo_new_sub_path(cairo);
    cairo_arc(cairo, p.x(), p.y(), 2.2, 0, 2 * std::numbers::pi);
    cairo_fill(cairo);
  }
}

// Right of the plot: the marker kinds, the region and the unheard scans when drawn; returns
// the baseline below the last entry.
double draw_localize_legend(cairo_t* cairo, const LocalizePlot& plot, const PlotArea& area,
                            const ValueRange& range) {
  double ly = area.top + 10;
  const std::pair<PlotMarkerKind, const char*> entries[] = {
      {PlotMarkerKind::estimate, "estimate / detection"},
      {PlotMarkerKind::alternative, "other hypothesis"},
      {PlotMarkerKind::lag_corrected, "lag-corrected"},
      {PlotMarkerKind::truth, "truth"}};
  for (const auto& [kind, label] : entries) {
    set_colour(cairo, marker_colour(kind));
    cairo_new_sub_path(cairo);
    cairo_arc(cairo, area.right + 22, ly - 4, 5, 0, 2 * std::numbers::pi);
    cairo_fill(cairo);
    set_colour(cairo, kInkColour);
    draw_text(cairo, label, area.right + 32, ly, 11);
    ly += 20;
  }
  if (!plot.region_cells.empty()) {
    set_colour(cairo, kRegion, 0.35);
    cairo_rectangle(cairo, area.right + 17, ly - 9, 10, 10);
    cairo_fill(cairo);
    set_colour(cairo, kInkColour);
    draw_text(cairo, plot.region_label, area.right + 32, ly, 11);
    ly += 20;
  }
  if (range.any_unheard) {
    set_colour(cairo, kUnheard);
    cairo_set_line_width(cairo, 1.5);
    cairo_new_sub_path(cairo);
    cairo_arc(cairo, area.right + 22, ly - 4, 4, 0, 2 * std::numbers::pi);
    cairo_stroke(cairo);
    set_colour(cairo, kInkColour);
    draw_text(cairo, "scan below the floor", area.right + 32, ly, 11);
    ly += 20;
  }
  return ly;
}

// The value's colour bar under the legend, highest on top.
void draw_colour_bar(cairo_t* cairo, const std::string& label, double x, double y,
                     const ValueRange& range) {
  draw_text(cairo, label, x + 16, y, 11);
  for (int i = 0; i < 100; ++i) {
    set_colour(cairo, ramp(1.0 - i / 99.0));
    cairo_rectangle(cairo, x + 20, y + 10 + i * 2, 14, 2.2);
    cairo_fill(cairo);
  }
  set_colour(cairo, kInkColour);
  draw_text(cairo, model::format_number(range.highest, 4), x + 40, y + 18, 11);
  draw_text(cairo, model::format_number(range.lowest, 4), x + 40, y + 210, 11);
}

}  // namespace

void plot_localization(const LocalizePlot& plot, const std::string& path, int width, int height) {
  const LocalizeView view = localize_view(plot, width, height);
  const ValueRange range = value_range(plot.values);
  draw_to_file(path, width, height, [&](cairo_t* cairo) {
    set_colour(cairo, kInkColour);
    draw_text(cairo, plot.title, width / 2.0, 34, 18, Anchor::centre, true);
    draw_localize_axes(cairo, view);
    // Region, walls, path and markers stay in the frame (a 2-sigma ellipse can reach far out).
    cairo_save(cairo);
    cairo_rectangle(cairo, view.area.left, view.area.top, view.area.right - view.area.left,
                    view.area.bottom - view.area.top);
    cairo_clip(cairo);
    draw_region(cairo, plot, view);
    draw_walls(cairo, plot, view);
    draw_path(cairo, plot, view, range);
    draw_markers(cairo, plot, view, width);
    cairo_restore(cairo);
    draw_outside_markers(cairo, view);
    const double ly = draw_localize_legend(cairo, plot, view.area, range);
    if (range.any_value) draw_colour_bar(cairo, plot.value_label, view.area.right, ly + 20, range);
  });
}

}  // namespace rigdesign::render
