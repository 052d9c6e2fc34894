#include "rigdesign/render/localize_plot.hpp"

#include <Eigen/Eigenvalues>
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

constexpr Rgb kEstimate{0.85, 0.1, 0.1};
constexpr Rgb kAlternative{0.95, 0.55, 0.1};
constexpr Rgb kTruth{0.1, 0.6, 0.2};
constexpr Rgb kLagCorrected{0.55, 0.2, 0.75};
constexpr Rgb kWall{0.3, 0.3, 0.3};
constexpr Rgb kUnheard{0.62, 0.62, 0.62};
constexpr Rgb kRegion{
    0.95, 0.6, 0.2};  // a credible region, under the markers  // scans below the receiver's floor

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

Rgb colour_of(PlotMarkerKind kind) {
  switch (kind) {
    case PlotMarkerKind::estimate: return kEstimate;
    case PlotMarkerKind::alternative: return kAlternative;
    case PlotMarkerKind::truth: return kTruth;
    case PlotMarkerKind::detection: return kEstimate;
    case PlotMarkerKind::lag_corrected: return kLagCorrected;
    case PlotMarkerKind::artifact: return kTruth;
  }
  return kInkColour;
}

}  // namespace

void plot_localization(const LocalizePlot& plot, const std::string& path, int width, int height) {
  render::draw_to_file(path, width, height, [&](cairo_t* cairo) {
    model::Vec2 low = model::Vec2::Constant(1e300), high = model::Vec2::Constant(-1e300);
    const auto extend = [&](const model::Vec2& p) {
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    };
    // The region of interest is where the robot went (the walls, the credible region), with a
    // margin of half its size (5 m at least): a wild estimate 150 m away must not shrink the
    // path to a dot.
    for (const model::Vec3& p : plot.path) extend(p.head<2>());
    for (const auto& [a, b] : plot.walls) {
      extend(a);
      extend(b);
    }
    for (const model::Vec2& c : plot.region_cells) extend(c);  // the stated region, whole
    if (low.x() > high.x()) {
      for (const PlotMarker& m : plot.markers) extend(m.position.head<2>());
    }
    if (low.x() > high.x()) low = high = model::Vec2::Zero();
    const double margin = std::max(5.0, 0.5 * (high - low).maxCoeff());
    const model::Vec2 region_low = low - model::Vec2::Constant(margin);
    const model::Vec2 region_high = high + model::Vec2::Constant(margin);
    const auto in_region = [&](const model::Vec2& p) {
      return (p.array() >= region_low.array()).all() && (p.array() <= region_high.array()).all();
    };
    std::vector<const PlotMarker*> outside;
    for (const PlotMarker& m : plot.markers) {
      if (in_region(m.position.head<2>())) {
        extend(m.position.head<2>());
      } else {
        outside.push_back(&m);
      }
    }
    const double left = 70, top = 60, right = width - 150.0;
    // Room under the x axis for a note per marker left out.
    const double bottom =
        height - 60.0 -
        (outside.empty() ? 0.0 : 15.0 * static_cast<double>(outside.size() + 1) + 8);
    const model::Vec2 centre = 0.5 * (low + high);
    const double span = std::max({high.x() - low.x(),
                                  (high.y() - low.y()) * (right - left) / (bottom - top), 1.0}) *
                        1.1;
    const double scale = (right - left) / span;  // pixels per metre, equal on both axes
    const auto px = [&](const model::Vec2& p) {
      return model::Vec2((left + right) / 2 + (p.x() - centre.x()) * scale,
                         (top + bottom) / 2 - (p.y() - centre.y()) * scale);
    };
    set_colour(cairo, kInkColour);
    draw_text(cairo, plot.title, width / 2.0, 34, 18, Anchor::centre, true);
    // Grid every 1, 2, 5 or 10 ... m, about 8 lines across.
    const double raw = span / 8;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    const double step = magnitude * (raw / magnitude > 5   ? 10
                                     : raw / magnitude > 2 ? 5
                                     : raw / magnitude > 1 ? 2
                                                           : 1);
    cairo_set_line_width(cairo, 1);
    const model::Vec2 corner_low(centre.x() - span / 2,
                                 centre.y() - span * (bottom - top) / (right - left) / 2);
    const model::Vec2 corner_high(centre.x() + span / 2,
                                  centre.y() + span * (bottom - top) / (right - left) / 2);
    for (double x = std::ceil(corner_low.x() / step) * step; x <= corner_high.x(); x += step) {
      set_colour(cairo, kGridColour);
      cairo_move_to(cairo, px({x, 0}).x(), top);
      cairo_line_to(cairo, px({x, 0}).x(), bottom);
      cairo_stroke(cairo);
      set_colour(cairo, kInkColour);
      draw_text(cairo, model::format_number(x, 6), px({x, 0}).x(), bottom + 18, 12, Anchor::centre);
    }
    for (double y = std::ceil(corner_low.y() / step) * step; y <= corner_high.y(); y += step) {
      set_colour(cairo, kGridColour);
      cairo_move_to(cairo, left, px({0, y}).y());
      cairo_line_to(cairo, right, px({0, y}).y());
      cairo_stroke(cairo);
      set_colour(cairo, kInkColour);
      draw_text(cairo, model::format_number(y, 6), left - 6, px({0, y}).y() + 4, 12, Anchor::right);
    }
    draw_text(cairo, "x [m]", (left + right) / 2, bottom + 36, 13, Anchor::centre);
    draw_text(cairo, "y [m]", 20, top - 10, 13, Anchor::left);
    // Walls, path and markers stay in the frame (a 2-sigma ellipse can reach far out).
    cairo_save(cairo);
    cairo_rectangle(cairo, left, top, right - left, bottom - top);
    cairo_clip(cairo);
    set_colour(cairo, kRegion, 0.35);
    for (const model::Vec2& c : plot.region_cells) {
      const model::Vec2 corner = px(c - model::Vec2::Constant(plot.region_cell / 2));
      const model::Vec2 opposite = px(c + model::Vec2::Constant(plot.region_cell / 2));
      cairo_rectangle(cairo, corner.x(), opposite.y(), opposite.x() - corner.x(),
                      corner.y() - opposite.y());
    }
    cairo_fill(cairo);
    set_colour(cairo, kWall);
    cairo_set_line_width(cairo, 4);
    for (const auto& [a, b] : plot.walls) {
      cairo_move_to(cairo, px(a).x(), px(a).y());
      cairo_line_to(cairo, px(b).x(), px(b).y());
      cairo_stroke(cairo);
    }
    double lowest = 0, highest = 1;
    bool any_value = false, any_unheard = false;
    for (const double v : plot.values) {
      if (std::isnan(v)) {
        any_unheard = true;
        continue;
      }
      lowest = any_value ? std::min(lowest, v) : v;
      highest = any_value ? std::max(highest, v) : v;
      any_value = true;
    }
    highest = std::max(lowest + 1e-9, highest);
    for (std::size_t i = 0; i < plot.path.size(); ++i) {
      const model::Vec2 p = px(plot.path[i].head<2>());
      const bool valued = plot.values.size() == plot.path.size();
      if (valued && std::isnan(plot.values[i])) {  // a scan that heard nothing: a grey ring
        set_colour(cairo, kUnheard, 0.8);
        cairo_set_line_width(cairo, 1);
        cairo_new_sub_path(cairo);
        cairo_arc(cairo, p.x(), p.y(), 2.0, 0, 2 * std::numbers::pi);
        cairo_stroke(cairo);
        continue;
      }
      set_colour(cairo, valued ? ramp((plot.values[i] - lowest) / (highest - lowest)) : kInkColour,
                 0.8);
      cairo_new_sub_path(cairo);
      cairo_arc(cairo, p.x(), p.y(), 2.2, 0, 2 * std::numbers::pi);
      cairo_fill(cairo);
    }
    for (const PlotMarker& marker : plot.markers) {
      if (std::find(outside.begin(), outside.end(), &marker) != outside.end()) continue;
      const model::Vec2 p = px(marker.position.head<2>());
      set_colour(cairo, colour_of(marker.kind));
      cairo_set_line_width(cairo, 2);
      if (marker.covariance.trace() > 0) {  // the 2-sigma ellipse
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(marker.covariance);
        const Eigen::Vector2d axes = 2.0 * eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt() * scale;
        const double angle = std::atan2(eigen.eigenvectors()(1, 1), eigen.eigenvectors()(0, 1));
        if (axes.maxCoeff() < 4 * width) {
          cairo_save(cairo);
          cairo_translate(cairo, p.x(), p.y());
          cairo_rotate(cairo, -angle);
          cairo_scale(cairo, std::max(axes(1), 0.5), std::max(axes(0), 0.5));
          cairo_arc(cairo, 0, 0, 1, 0, 2 * std::numbers::pi);
          cairo_restore(cairo);
          cairo_stroke(cairo);
        }
      }
      if (marker.kind == PlotMarkerKind::truth || marker.kind == PlotMarkerKind::artifact) {
        cairo_set_line_width(cairo, 3);
        cairo_move_to(cairo, p.x() - 7, p.y() - 7);
        cairo_line_to(cairo, p.x() + 7, p.y() + 7);
        cairo_move_to(cairo, p.x() - 7, p.y() + 7);
        cairo_line_to(cairo, p.x() + 7, p.y() - 7);
        cairo_stroke(cairo);
      } else {
        cairo_new_sub_path(cairo);
        cairo_arc(cairo, p.x(), p.y(), 6, 0, 2 * std::numbers::pi);
        cairo_fill(cairo);
      }
      if (!marker.label.empty()) {
        set_colour(cairo, kInkColour);
        draw_text(cairo, marker.label, p.x() + 9, p.y() - 9, 12);
      }
    }
    cairo_restore(cairo);
    // Markers outside the region: an arrow on the frame's edge toward each, and a note of
    // where they are, so nothing is dropped silently.
    double note_y = bottom + 58;
    if (!outside.empty()) {
      set_colour(cairo, kInkColour);
      draw_text(cairo,
                std::to_string(outside.size()) +
                    " marker(s) beyond the region shown (the path plus a margin of " +
                    model::format_number(margin, 3) + " m), not to scale:",
                left, note_y, 11, Anchor::left, true);
    }
    for (const PlotMarker* marker : outside) {
      const model::Vec2 target = px(marker->position.head<2>());
      const model::Vec2 middle((left + right) / 2, (top + bottom) / 2);
      const model::Vec2 towards = (target - middle).normalized();
      // Where the ray from the middle leaves the plot frame.
      const double reach =
          std::min(std::abs(towards.x()) > 1e-9
                       ? ((towards.x() > 0 ? right : left) - middle.x()) / towards.x()
                       : 1e300,
                   std::abs(towards.y()) > 1e-9
                       ? ((towards.y() > 0 ? bottom : top) - middle.y()) / towards.y()
                       : 1e300);
      const model::Vec2 tip = middle + towards * (reach - 4);
      const model::Vec2 side(-towards.y(), towards.x());
      const model::Vec2 base = tip - towards * 16;
      set_colour(cairo, colour_of(marker->kind));
      cairo_move_to(cairo, tip.x(), tip.y());
      cairo_line_to(cairo, base.x() + side.x() * 7, base.y() + side.y() * 7);
      cairo_line_to(cairo, base.x() - side.x() * 7, base.y() - side.y() * 7);
      cairo_close_path(cairo);
      cairo_fill(cairo);
      const std::string where = "(" + model::format_number(marker->position.x(), 4) + ", " +
                                model::format_number(marker->position.y(), 4) + ") m";
      set_colour(cairo, kInkColour);
      draw_text(cairo,
                (marker->label.empty() ? std::string("marker") : marker->label) + " " + where,
                base.x() - towards.x() * 60, base.y() - towards.y() * 14, 11, Anchor::centre);
      note_y += 15;
      draw_text(
          cairo,
          "  " + (marker->label.empty() ? std::string("marker") : marker->label) + " at " + where,
          left, note_y, 11);
    }
    // Legend and colour bar.
    double ly = top + 10;
    const std::pair<PlotMarkerKind, const char*> entries[] = {
        {PlotMarkerKind::estimate, "estimate / detection"},
        {PlotMarkerKind::alternative, "other hypothesis"},
        {PlotMarkerKind::lag_corrected, "lag-corrected"},
        {PlotMarkerKind::truth, "truth"}};
    for (const auto& [kind, label] : entries) {
      set_colour(cairo, colour_of(kind));
      cairo_new_sub_path(cairo);
      cairo_arc(cairo, right + 22, ly - 4, 5, 0, 2 * std::numbers::pi);
      cairo_fill(cairo);
      set_colour(cairo, kInkColour);
      draw_text(cairo, label, right + 32, ly, 11);
      ly += 20;
    }
    if (!plot.region_cells.empty()) {
      set_colour(cairo, kRegion, 0.35);
      cairo_rectangle(cairo, right + 17, ly - 9, 10, 10);
      cairo_fill(cairo);
      set_colour(cairo, kInkColour);
      draw_text(cairo, plot.region_label, right + 32, ly, 11);
      ly += 20;
    }
    if (any_unheard) {
      set_colour(cairo, kUnheard);
      cairo_set_line_width(cairo, 1.5);
      cairo_new_sub_path(cairo);
      cairo_arc(cairo, right + 22, ly - 4, 4, 0, 2 * std::numbers::pi);
      cairo_stroke(cairo);
      set_colour(cairo, kInkColour);
      draw_text(cairo, "scan below the floor", right + 32, ly, 11);
      ly += 20;
    }
    if (any_value) {
      ly += 20;
      draw_text(cairo, plot.value_label, right + 16, ly, 11);
      for (int i = 0; i < 100; ++i) {
        set_colour(cairo, ramp(1.0 - i / 99.0));
        cairo_rectangle(cairo, right + 20, ly + 10 + i * 2, 14, 2.2);
        cairo_fill(cairo);
      }
      set_colour(cairo, kInkColour);
      draw_text(cairo, model::format_number(highest, 4), right + 40, ly + 18, 11);
      draw_text(cairo, model::format_number(lowest, 4), right + 40, ly + 210, 11);
    }
  });
}

}  // namespace rigdesign::render
