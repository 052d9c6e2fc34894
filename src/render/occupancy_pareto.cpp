#include "rigdesign/render/occupancy_pareto.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cairo_canvas.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::render {
namespace {

using render::Anchor;
using render::draw_text;
using render::set_colour;

double f2_or_worst(double f2) {
  return std::isnan(f2) ? -1.0 : f2;
}

// Fast (green) to slow (red) along the log of the time, so decades read evenly.
Rgb speed_colour(double share) {
  share = std::clamp(share, 0.0, 1.0);
  return {0.15 + 0.75 * share, 0.65 - 0.45 * share, 0.2};
}

// 1, 2 or 5 times a power of ten, about `count` steps across `span`.
double nice_step(double span, double count) {
  const double raw = std::max(span, 1e-9) / count;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double ratio = raw / magnitude;
  return magnitude * (ratio > 5 ? 10 : ratio > 2 ? 5 : ratio > 1 ? 2 : 1);
}

}  // namespace

std::vector<std::size_t> pareto_front(const std::vector<ParetoPoint>& points) {
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const ParetoPoint& a = points[i];
    const bool dominated = std::any_of(points.begin(), points.end(), [&](const ParetoPoint& b) {
      const bool no_worse = f2_or_worst(b.f2) >= f2_or_worst(a.f2) &&
                            b.ghost_area <= a.ghost_area && b.update_ms <= a.update_ms;
      const bool better = f2_or_worst(b.f2) > f2_or_worst(a.f2) || b.ghost_area < a.ghost_area ||
                          b.update_ms < a.update_ms;
      return no_worse && better;
    });
    if (!dominated) front.push_back(i);
  }
  return front;
}

void plot_occupancy_pareto(const std::vector<ParetoPoint>& points, const std::string& title,
                           const std::string& path, int width, int height) {
  const std::vector<std::size_t> front = pareto_front(points);
  render::draw_to_file(path, width, height, [&](cairo_t* cairo) {
    const double left = 80, top = 60, right = width - 190.0, bottom = height - 70.0;
    double ghost_max = 0.0, ms_low = 1e300, ms_high = 0.0;
    for (const ParetoPoint& p : points) {
      ghost_max = std::max(ghost_max, p.ghost_area);
      ms_low = std::min(ms_low, std::max(p.update_ms, 1e-3));
      ms_high = std::max(ms_high, std::max(p.update_ms, 1e-3));
    }
    ghost_max = std::max(ghost_max * 1.1, 0.01);
    const double x_step = nice_step(ghost_max, 8);
    ghost_max = std::ceil(ghost_max / x_step) * x_step;
    const auto px = [&](double ghost, double f2) {
      return std::pair{left + ghost / ghost_max * (right - left), bottom - f2 * (bottom - top)};
    };
    set_colour(cairo, kInkColour);
    draw_text(cairo, title, width / 2.0, 34, 18, Anchor::centre, true);
    cairo_set_line_width(cairo, 1);
    for (double x = 0; x <= ghost_max + 1e-12; x += x_step) {
      set_colour(cairo, kGridColour);
      cairo_move_to(cairo, px(x, 0).first, top);
      cairo_line_to(cairo, px(x, 0).first, bottom);
      cairo_stroke(cairo);
      set_colour(cairo, kInkColour);
      draw_text(cairo, model::format_number(x, 4), px(x, 0).first, bottom + 18, 12, Anchor::centre);
    }
    for (int i = 0; i <= 10; ++i) {
      const double f2 = i / 10.0;
      set_colour(cairo, kGridColour);
      cairo_move_to(cairo, left, px(0, f2).second);
      cairo_line_to(cairo, right, px(0, f2).second);
      cairo_stroke(cairo);
      set_colour(cairo, kInkColour);
      draw_text(cairo, model::format_number(f2, 2), left - 8, px(0, f2).second + 4, 12,
                Anchor::right);
    }
    draw_text(cairo, "mean ghost area over the cell [m^2] (lower is better)", (left + right) / 2,
              height - 28.0, 13, Anchor::centre);
    draw_text(cairo, "mean F2 near the person", 14, top - 14, 13);
    const double log_span = std::max(std::log(ms_high / ms_low), 1e-9);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const ParetoPoint& p = points[i];
      if (std::isnan(p.f2)) continue;
      const auto [x, y] = px(p.ghost_area, p.f2);
      set_colour(cairo, speed_colour(std::log(std::max(p.update_ms, 1e-3) / ms_low) / log_span));
      cairo_new_sub_path(cairo);
      cairo_arc(cairo, x, y, 6, 0, 2 * std::numbers::pi);
      cairo_fill(cairo);
      const bool on_front = std::find(front.begin(), front.end(), i) != front.end();
      set_colour(cairo, kInkColour);
      if (on_front) {
        cairo_set_line_width(cairo, 2);
        cairo_new_sub_path(cairo);
        cairo_arc(cairo, x, y, 10, 0, 2 * std::numbers::pi);
        cairo_stroke(cairo);
      }
      draw_text(cairo, p.label, x + 12, y - 6, 10);
    }
    // Legend: the time scale and the ring.
    const double lx = right + 24;
    draw_text(cairo, "ms per update", lx, top + 10, 12, Anchor::left, true);
    for (int i = 0; i < 5; ++i) {
      const double share = i / 4.0;
      set_colour(cairo, speed_colour(share));
      cairo_new_sub_path(cairo);
      cairo_arc(cairo, lx + 6, top + 32 + i * 22, 6, 0, 2 * std::numbers::pi);
      cairo_fill(cairo);
      set_colour(cairo, kInkColour);
      draw_text(cairo, model::format_number(ms_low * std::exp(share * log_span), 3), lx + 20,
                top + 36 + i * 22, 11);
    }
    cairo_set_line_width(cairo, 2);
    cairo_new_sub_path(cairo);
    cairo_arc(cairo, lx + 6, top + 160, 10, 0, 2 * std::numbers::pi);
    cairo_stroke(cairo);
    draw_text(cairo, "Pareto-optimal", lx + 22, top + 164, 11);
  });
}

}  // namespace rigdesign::render
