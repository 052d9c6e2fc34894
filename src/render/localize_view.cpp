#include "localize_view.hpp"

#include <algorithm>

namespace rigdesign::render {
namespace {

constexpr double kMinMargin = 5.0;  // [m] around the region of interest
constexpr double kNoteRow = 15.0;   // [px] a note under the x axis per marker left out

// The bounding box of what a view keeps in, grown point by point.
struct Bounds {
  model::Vec2 low = model::Vec2::Constant(1e300), high = model::Vec2::Constant(-1e300);
  void extend(const model::Vec2& p) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  bool empty() const { return low.x() > high.x(); }
};

// Where the robot went: the path, the walls and the stated region, whole.
Bounds region_of_interest(const LocalizePlot& plot) {
  Bounds bounds;
  for (const model::Vec3& p : plot.path) bounds.extend(p.head<2>());
  for (const auto& [a, b] : plot.walls) {
    bounds.extend(a);
    bounds.extend(b);
  }
  for (const model::Vec2& c : plot.region_cells) bounds.extend(c);
  if (bounds.empty()) {
    for (const PlotMarker& m : plot.markers) bounds.extend(m.position.head<2>());
  }
  if (bounds.empty()) bounds.low = bounds.high = model::Vec2::Zero();
  return bounds;
}

}  // namespace

bool LocalizeView::shows(const PlotMarker& marker) const {
  return std::find(outside.begin(), outside.end(), &marker) == outside.end();
}

LocalizeView localize_view(const LocalizePlot& plot, int width, int height) {
  LocalizeView view;
  Bounds bounds = region_of_interest(plot);
  view.margin = std::max(kMinMargin, 0.5 * (bounds.high - bounds.low).maxCoeff());
  const model::Vec2 region_low = bounds.low - model::Vec2::Constant(view.margin);
  const model::Vec2 region_high = bounds.high + model::Vec2::Constant(view.margin);
  for (const PlotMarker& m : plot.markers) {
    const model::Vec2 p = m.position.head<2>();
    if ((p.array() >= region_low.array()).all() && (p.array() <= region_high.array()).all()) {
      bounds.extend(p);
    } else {
      view.outside.push_back(&m);
    }
  }
  const double notes =
      view.outside.empty() ? 0.0 : kNoteRow * static_cast<double>(view.outside.size() + 1) + 8;
  view.area = {70, 60, width - 150.0, height - 60.0 - notes};
  const PlotArea& a = view.area;
  view.centre = 0.5 * (bounds.low + bounds.high);
  view.span =
      std::max({bounds.high.x() - bounds.low.x(),
                (bounds.high.y() - bounds.low.y()) * (a.right - a.left) / (a.bottom - a.top),
                1.0}) *
      1.1;
  view.scale = (a.right - a.left) / view.span;
  return view;
}

}  // namespace rigdesign::render
