#include "chart_axes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cairo_canvas.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::render {
namespace {

constexpr double kMarkLength = 5.0;  // [px] a tick mark outside a map's frame
// A tick past the range's end by less than this many steps is rounding, not a new tick.
constexpr double kEndSlack = 1e-9;

// The colour of a tick's line: grid lines stay pale under the data, marks are ink.
void set_line_colour(cairo_t* cairo, const Axis& axis, double value, TickLine line) {
  const bool ink = line == TickLine::mark || (axis.ink_at_zero && std::abs(value) < 1e-9);
  set_colour(cairo, ink ? kInkColour : kGridColour);
}

void draw_x_ticks(cairo_t* cairo, const PlotArea& area, const Axis& x, const TickLabelStyle& style,
                  TickLine line) {
  for (const double value : x.ticks) {
    const double at = x.pixel(value);
    set_line_colour(cairo, x, value, line);
    if (line == TickLine::mark) {
      cairo_move_to(cairo, at, area.bottom);
      cairo_line_to(cairo, at, area.bottom + kMarkLength);
    } else {
      cairo_move_to(cairo, at, x.grid_from_bottom ? area.bottom : area.top);
      cairo_line_to(cairo, at, x.grid_from_bottom ? area.top : area.bottom);
    }
    cairo_stroke(cairo);
    set_colour(cairo, kInkColour);
    draw_text(cairo, model::format_number(value, x.digits), at, area.bottom + style.below,
              style.size, Anchor::centre);
  }
}

void draw_y_ticks(cairo_t* cairo, const PlotArea& area, const Axis& y, const TickLabelStyle& style,
                  TickLine line) {
  for (const double value : y.ticks) {
    const double at = y.pixel(value);
    set_line_colour(cairo, y, value, line);
    cairo_move_to(cairo, line == TickLine::grid ? area.left : area.left - kMarkLength, at);
    cairo_line_to(cairo, line == TickLine::grid ? area.right : area.left, at);
    cairo_stroke(cairo);
    set_colour(cairo, kInkColour);
    draw_text(cairo, model::format_number(value, y.digits), area.left - style.beside,
              at + style.lift, style.size, Anchor::right);
  }
}

}  // namespace

double tick_step(double span, double count, StepRounding rounding,
                 std::span<const double> factors) {
  const double raw = std::max(span, 1e-9) / count;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double ratio = raw / magnitude;  // in [1, 10)
  if (rounding == StepRounding::down) {
    double factor = factors.front();
    for (const double f : factors) {
      if (ratio > f) factor = f;
    }
    return magnitude * factor;
  }
  for (const double f : factors) {
    if (ratio <= f) return magnitude * f;
  }
  return magnitude * 10;
}

std::vector<double> tick_values(double low, double high, double step) {
  std::vector<double> values;
  for (double value = std::ceil(low / step) * step; value <= high + kEndSlack * step;
       value += step) {
    values.push_back(value);
  }
  return values;
}

void draw_ticks(cairo_t* cairo, const PlotArea& area, const Axis& x, const Axis& y,
                const TickLabelStyle& style, TickLine line) {
  cairo_set_line_width(cairo, 1);
  draw_x_ticks(cairo, area, x, style, line);
  draw_y_ticks(cairo, area, y, style, line);
  set_colour(cairo, kInkColour);
}

void draw_x_title(cairo_t* cairo, const PlotArea& area, const std::string& text, double below,
                  double size) {
  draw_text(cairo, text, (area.left + area.right) / 2, area.bottom + below, size, Anchor::centre);
}

void draw_y_title(cairo_t* cairo, const PlotArea& area, const std::string& text, double x,
                  double size) {
  cairo_save(cairo);
  cairo_translate(cairo, x, (area.top + area.bottom) / 2);
  cairo_rotate(cairo, -std::numbers::pi / 2);
  draw_text(cairo, text, 0, 0, size, Anchor::centre);
  cairo_restore(cairo);
}

}  // namespace rigdesign::render
