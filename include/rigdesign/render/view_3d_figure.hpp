#pragma once
/// A 3D view as a figure that explains itself: the rendered view (view_3d.hpp) with a title,
/// a legend naming each sensor in its colour, each sensor's name at its origin, and a scale
/// bar, as PNG, or SVG with the view embedded and every word real text.
#include <string>
#include <vector>

#include "rigdesign/render/view_3d.hpp"

namespace rigdesign::render {

struct LegendEntry {
  Rgb colour;
  std::string text;
};

struct ViewLabel {
  model::Vec3 at = model::Vec3::Zero();  ///< robot frame [m]
  std::string text;
  Rgb colour;
};

struct View3dOverlay {
  std::string title;
  std::string subtitle;  ///< one line under the title, e.g. what was cut away
  std::vector<LegendEntry> legend;
  std::vector<ViewLabel> labels;
};

/// Renders the meshes and draws the overlay over them; `path` ends in .png or .svg.
void render_view_3d(const std::vector<ColouredMesh>& meshes, const View3dSettings& settings,
                    const View3dOverlay& overlay, const std::string& path);

/// The bare view as PNG (no overlay), for pictures that are only pixels.
void render_view_3d(const std::vector<ColouredMesh>& meshes, const View3dSettings& settings,
                    const std::string& png_path);

}  // namespace rigdesign::render
