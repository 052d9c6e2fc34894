#pragma once
// The markers of a localisation plot (estimates, other hypotheses, truth, detections,
// artifacts): inside the view with their uncertainty, beyond it as arrows on the frame's edge
// and notes, so none is dropped silently. Private to render/.
#include <cairo.h>

#include "localize_view.hpp"
#include "rigdesign/render/palette.hpp"

namespace rigdesign::render {

Rgb marker_colour(PlotMarkerKind kind);

/// Each marker the view shows: its 2-sigma ellipse, a cross (truth, artifact) or a dot, and
/// its label. The caller clips to the plot area: an ellipse can reach far out. One wider than
/// four canvas widths is left out: at most a near-straight sliver of it would cross the frame.
void draw_markers(cairo_t* cairo, const LocalizePlot& plot, const LocalizeView& view, int width);

/// Each marker beyond the view: an arrow on the frame's edge toward it, labelled with its
/// coordinates, and a note of where it is under the x axis.
void draw_outside_markers(cairo_t* cairo, const LocalizeView& view);

}  // namespace rigdesign::render
