#include "rigdesign/render/margin_plot.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

#include "cairo_canvas.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::render {
namespace {

constexpr Rgb kCurve{0.1, 0.35, 0.7};
constexpr Rgb kGridChoice{0.0, 0.55, 0.25};
constexpr Rgb kRefined{0.85, 0.1, 0.1};
constexpr Rgb kMiss{0.95, 0.85, 0.85};

Rgb sector_colour(std::size_t index) {
  constexpr Rgb kColours[] = {{0.55, 0.35, 0.0}, {0.45, 0.2, 0.6}, {0.0, 0.5, 0.5},
                              {0.6, 0.6, 0.1}, {0.3, 0.3, 0.3}};
  return kColours[index % std::size(kColours)];
}

// A round tick spacing giving about five ticks over `span`.
double tick_step(double span) {
  const double magnitude = std::pow(10.0, std::floor(std::log10(span / 5)));
  const double ratio = span / magnitude;
  return magnitude * (ratio > 25 ? 5 : ratio > 10 ? 2 : 1);
}

}  // namespace

void plot_margin_curve(const MarginCurve& curve, const std::string& title,
                       const std::string& path, int width, int height) {
  draw_to_file(path, width, height, [&](cairo_t* cairo) {
    const double left = 80, top = 60, right = width - 30.0, bottom = height - 70.0;
    double x_low = curve.grid_choice, x_high = curve.grid_choice;
    double y_low = 0.0, y_high = 0.0;
    const auto varies = [](const std::vector<double>& values) {
      return !values.empty() && *std::max_element(values.begin(), values.end()) -
                                        *std::min_element(values.begin(), values.end()) > 1e-9;
    };
    for (const double x : curve.at) {
      x_low = std::min(x_low, x);
      x_high = std::max(x_high, x);
    }
    for (const double margin : curve.smallest) {
      y_low = std::min(y_low, margin);
      y_high = std::max(y_high, margin);
    }
    for (const auto& [name, margins] : curve.sectors) {
      if (!varies(margins)) continue;
      for (const double margin : margins) {
        y_low = std::min(y_low, margin);
        y_high = std::max(y_high, margin);
      }
    }
    for (const double g : curve.grid) {
      x_low = std::min(x_low, g);
      x_high = std::max(x_high, g);
    }
    if (x_high - x_low < 1e-9) x_high = x_low + 1.0;
    const double y_pad = std::max(1.0, 0.08 * (y_high - y_low));
    y_low -= y_pad;
    y_high += y_pad;
    const auto px = [&](double x) { return left + (right - left) * (x - x_low) / (x_high - x_low); };
    const auto py = [&](double y) { return bottom - (bottom - top) * (y - y_low) / (y_high - y_low); };

    set_colour(cairo, kInkColour);
    draw_text(cairo, title, width / 2.0, 32, 17, Anchor::centre, true);
    // Below zero a sector threshold is missed.
    set_colour(cairo, kMiss);
    cairo_rectangle(cairo, left, py(0), right - left, bottom - py(0));
    cairo_fill(cairo);
    cairo_set_line_width(cairo, 1);
    const double x_step = tick_step(x_high - x_low);
    for (double x = std::ceil(x_low / x_step) * x_step; x <= x_high + 1e-9; x += x_step) {
      set_colour(cairo, kGridColour);
      cairo_move_to(cairo, px(x), top);
      cairo_line_to(cairo, px(x), bottom);
      cairo_stroke(cairo);
      set_colour(cairo, kInkColour);
      draw_text(cairo, model::format_number(x, 4), px(x), bottom + 20, 13, Anchor::centre);
    }
    const double y_step = tick_step(y_high - y_low);
    for (double y = std::ceil(y_low / y_step) * y_step; y <= y_high + 1e-9; y += y_step) {
      set_colour(cairo, std::abs(y) < 1e-9 ? kInkColour : kGridColour);
      cairo_move_to(cairo, left, py(y));
      cairo_line_to(cairo, right, py(y));
      cairo_stroke(cairo);
      set_colour(cairo, kInkColour);
      draw_text(cairo, model::format_number(y, 4), left - 8, py(y) + 5, 13, Anchor::right);
    }
    draw_text(cairo, curve.axis_label, (left + right) / 2, height - 25.0, 14, Anchor::centre);
    cairo_save(cairo);
    cairo_translate(cairo, 24, (top + bottom) / 2);
    cairo_rotate(cairo, -std::numbers::pi / 2);
    draw_text(cairo, "smallest SC margin to the sector thresholds [points]", 0, 0, 14,
              Anchor::centre);
    cairo_restore(cairo);

    const auto polyline = [&](const std::vector<double>& margins) {
      for (std::size_t i = 0; i < margins.size() && i < curve.at.size(); ++i) {
        i == 0 ? cairo_move_to(cairo, px(curve.at[i]), py(margins[i]))
               : cairo_line_to(cairo, px(curve.at[i]), py(margins[i]));
      }
      cairo_stroke(cairo);
    };
    // The sectors this axis changes, thin and named at their right end; the rig's smallest
    // margin (what the search and the refinement widen) thick on top.
    for (std::size_t s = 0; s < curve.sectors.size(); ++s) {
      const auto& [name, margins] = curve.sectors[s];
      if (!varies(margins)) continue;
      set_colour(cairo, sector_colour(s));
      cairo_set_line_width(cairo, 1.3);
      polyline(margins);
      draw_text(cairo, "sector " + name, px(curve.at.back()) - 4, py(margins.back()) - 6, 12,
                Anchor::right);
    }
    set_colour(cairo, kCurve);
    cairo_set_line_width(cairo, 2.5);
    polyline(curve.smallest);
    if (!curve.at.empty())
      draw_text(cairo, "smallest (the rig)", px(curve.at.front()) + 4,
                py(curve.smallest.front()) - 8, 12, Anchor::left, true);
    // The grid the search chose from, as ticks on the axis.
    set_colour(cairo, kInkColour);
    for (const double g : curve.grid) {
      cairo_move_to(cairo, px(g), bottom);
      cairo_line_to(cairo, px(g), bottom - 8);
    }
    cairo_stroke(cairo);
    const double dash[] = {6.0, 4.0};
    const bool same = std::abs(curve.refined - curve.grid_choice) < 1e-9;
    struct Marker {
      double x;
      Rgb colour;
      const char* label;
      double label_y;
    };
    const Marker markers[] = {{curve.grid_choice, kGridChoice, same ? "grid optimum = refined" : "grid optimum", top + 16},
                              {curve.refined, kRefined, "refined", top + 34}};
    for (const Marker& marker : markers) {
      if (same && &marker != &markers[0]) continue;
      set_colour(cairo, marker.colour);
      cairo_set_dash(cairo, dash, 2, 0);
      cairo_move_to(cairo, px(marker.x), top);
      cairo_line_to(cairo, px(marker.x), bottom);
      cairo_stroke(cairo);
      cairo_set_dash(cairo, nullptr, 0, 0);
      draw_text(cairo, marker.label, px(marker.x) + 5, marker.label_y, 13);
    }
  });
}

}  // namespace rigdesign::render
