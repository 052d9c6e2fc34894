#pragma once
// The axes every 2D chart here draws: a round tick step, the ticks over an axis's range, and
// the ticks drawn as grid lines (or as marks outside a framed map) with their labels. One
// place decides how an axis looks, so the charts read alike and a fix reaches all of them.
// Private to render/.
#include <cairo.h>

#include <functional>
#include <span>
#include <string>
#include <vector>

namespace rigdesign::render {

/// Where a chart plots its data, in canvas pixels (y grows downward).
struct PlotArea {
  double left = 0.0, top = 0.0, right = 0.0, bottom = 0.0;
};

/// Which way tick_step rounds span / count to a round step.
enum class StepRounding {
  up,    ///< the smallest round step at or above it: `count` intervals at the most
  down,  ///< the largest round step below it: `count` intervals at the least
};

/// The usual round factors: steps of 1, 2 or 5 times a power of ten.
inline constexpr double kOneTwoFive[] = {1.0, 2.0, 5.0};

/// A round tick spacing for about `count` intervals over `span`: one of `factors` (ascending,
/// in [1, 10)) times a power of ten, or ten times it when rounding up passes the last factor.
/// A span of zero or less is taken as 1e-9, so the step stays finite.
double tick_step(double span, double count, StepRounding rounding,
                 std::span<const double> factors = kOneTwoFive);

/// The multiples of `step` from the first at or above `low` up to `high`. Each tick is the
/// previous one plus `step`, as the charts have always placed them (to the last bit), and a
/// tick that this sum's rounding puts a hair (1e-9 steps) beyond `high` still counts, so a
/// range ending on a tick shows it.
std::vector<double> tick_values(double low, double high, double step);

/// One axis: its tick values, where each lands on the canvas and how its label reads.
struct Axis {
  std::vector<double> ticks;
  std::function<double(double)> pixel;  ///< value -> canvas x (x axis) or y (y axis)
  int digits = 6;                       ///< significant digits of the tick labels
  bool ink_at_zero = false;             ///< the grid line at 0 in ink, where a sign matters
  /// x grid lines drawn from the bottom edge up, as a chart that rises from the floor (the
  /// cross-section) has always drawn them; its SVG paths stay as they were.
  bool grid_from_bottom = false;
};

/// Tick-label type and placement [px]; the defaults suit 13 px labels.
struct TickLabelStyle {
  double size = 13.0;
  double below = 20.0;  ///< from the plot's bottom down to the x labels' baseline
  double beside = 8.0;  ///< from the plot's left edge to the y labels' right end
  double lift = 5.0;    ///< from a y tick down to its label's baseline: centres the digits
};

/// How a tick shows: a grid line across the plot area, or a short mark outside its frame
/// (on a map, where grid lines would hide cells).
enum class TickLine { grid, mark };

/// The x ticks, then the y ticks: each a line in the grid colour (ink for a mark) and its label
/// in ink. Leaves the line width at 1 and the colour at ink.
void draw_ticks(cairo_t* cairo, const PlotArea& area, const Axis& x, const Axis& y,
                const TickLabelStyle& style = {}, TickLine line = TickLine::grid);

/// The x axis's title, centred under the plot area with its baseline `below` its bottom.
void draw_x_title(cairo_t* cairo, const PlotArea& area, const std::string& text, double below,
                  double size = 14.0);

/// The y axis's title read bottom to top, centred on the plot area's height at canvas x `x`.
void draw_y_title(cairo_t* cairo, const PlotArea& area, const std::string& text, double x,
                  double size = 14.0);

}  // namespace rigdesign::render
