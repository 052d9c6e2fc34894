#include "localize_markers.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "cairo_canvas.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::render {
namespace {

// The 2-sigma ellipse of the marker's covariance, at p [px].
void draw_ellipse(cairo_t* cairo, const PlotMarker& marker, const model::Vec2& p, double scale,
                  int width) {
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

// A cross for what is known (truth, artifact), a dot for what was estimated or detected.
void draw_glyph(cairo_t* cairo, PlotMarkerKind kind, const model::Vec2& p) {
  if (kind == PlotMarkerKind::truth || kind == PlotMarkerKind::artifact) {
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
}

// Where the ray from the plot area's middle toward `target` [px] leaves it, as a distance
// along the unit direction `towards`.
double reach_to_edge(const PlotArea& area, const model::Vec2& middle, const model::Vec2& towards) {
  return std::min(std::abs(towards.x()) > 1e-9
                      ? ((towards.x() > 0 ? area.right : area.left) - middle.x()) / towards.x()
                      : 1e300,
                  std::abs(towards.y()) > 1e-9
                      ? ((towards.y() > 0 ? area.bottom : area.top) - middle.y()) / towards.y()
                      : 1e300);
}

std::string name_of(const PlotMarker& marker) {
  return marker.label.empty() ? std::string("marker") : marker.label;
}

}  // namespace

// What was estimated or detected in red, what is known in green.
Rgb marker_colour(PlotMarkerKind kind) {
  switch (kind) {
    case PlotMarkerKind::estimate:
    case PlotMarkerKind::detection: return {0.85, 0.1, 0.1};
    case PlotMarkerKind::alternative: return {0.95, 0.55, 0.1};
    case PlotMarkerKind::lag_corrected: return {0.55, 0.2, 0.75};
    case PlotMarkerKind::truth:
    case PlotMarkerKind::artifact: return {0.1, 0.6, 0.2};
  }
  return kInkColour;
}

void draw_markers(cairo_t* cairo, const LocalizePlot& plot, const LocalizeView& view, int width) {
  for (const PlotMarker& marker : plot.markers) {
    if (!view.shows(marker)) continue;
    const model::Vec2 p = view.px(marker.position.head<2>());
    set_colour(cairo, marker_colour(marker.kind));
    cairo_set_line_width(cairo, 2);
    if (marker.covariance.trace() > 0) draw_ellipse(cairo, marker, p, view.scale, width);
    draw_glyph(cairo, marker.kind, p);
    if (!marker.label.empty()) {
      set_colour(cairo, kInkColour);
      draw_text(cairo, marker.label, p.x() + 9, p.y() - 9, 12);
    }
  }
}

void draw_outside_markers(cairo_t* cairo, const LocalizeView& view) {
  const PlotArea& area = view.area;
  double note_y = area.bottom + 58;
  if (!view.outside.empty()) {
    set_colour(cairo, kInkColour);
    draw_text(cairo,
              std::to_string(view.outside.size()) +
                  " marker(s) beyond the region shown (the path plus a margin of " +
                  model::format_number(view.margin, 3) + " m), not to scale:",
              area.left, note_y, 11, Anchor::left, true);
  }
  for (const PlotMarker* marker : view.outside) {
    const model::Vec2 target = view.px(marker->position.head<2>());
    const model::Vec2 middle((area.left + area.right) / 2, (area.top + area.bottom) / 2);
    const model::Vec2 towards = (target - middle).normalized();
    const model::Vec2 tip = middle + towards * (reach_to_edge(area, middle, towards) - 4);
    const model::Vec2 side(-towards.y(), towards.x());
    const model::Vec2 base = tip - towards * 16;
    set_colour(cairo, marker_colour(marker->kind));
    cairo_move_to(cairo, tip.x(), tip.y());
    cairo_line_to(cairo, base.x() + side.x() * 7, base.y() + side.y() * 7);
    cairo_line_to(cairo, base.x() - side.x() * 7, base.y() - side.y() * 7);
    cairo_close_path(cairo);
    cairo_fill(cairo);
    const std::string where = "(" + model::format_number(marker->position.x(), 4) + ", " +
                              model::format_number(marker->position.y(), 4) + ") m";
    set_colour(cairo, kInkColour);
    draw_text(cairo, name_of(*marker) + " " + where, base.x() - towards.x() * 60,
              base.y() - towards.y() * 14, 11, Anchor::centre);
    note_y += 15;
    draw_text(cairo, "  " + name_of(*marker) + " at " + where, area.left, note_y, 11);
  }
}

}  // namespace rigdesign::render
