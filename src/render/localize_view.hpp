#pragma once
// Where a localisation plot looks: the region of interest (where the robot went, with a
// margin), the markers that lie beyond it, and metres to pixels at one scale on both axes.
// Private to render/.
#include <vector>

#include "chart_axes.hpp"
#include "rigdesign/render/localize_plot.hpp"

namespace rigdesign::render {

struct LocalizeView {
  PlotArea area;
  model::Vec2 centre = model::Vec2::Zero();  ///< [m] at the middle of the plot area
  double span = 1.0;                         ///< [m] across the plot area's width
  double scale = 1.0;                        ///< [px/m], equal on both axes
  double margin = 0.0;  ///< [m] around the path, walls and region that the view keeps
  std::vector<const PlotMarker*> outside;  ///< markers beyond the region, drawn as arrows

  model::Vec2 px(const model::Vec2& p) const {
    return model::Vec2((area.left + area.right) / 2 + (p.x() - centre.x()) * scale,
                       (area.top + area.bottom) / 2 - (p.y() - centre.y()) * scale);
  }
  bool shows(const PlotMarker& marker) const;
};

/// The view of `plot` on a width x height canvas. The region of interest is the path, the
/// walls and the stated credible region (the markers when there is none of those) with a
/// margin of half its size, 5 m at least: a wild estimate 150 m away must not shrink the path
/// to a dot. Markers beyond it are listed in `outside`, and the plot area leaves room under
/// the x axis for a note on each.
LocalizeView localize_view(const LocalizePlot& plot, int width, int height);

}  // namespace rigdesign::render
