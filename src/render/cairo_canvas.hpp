#pragma once
// One drawing routine, two file formats: PNG for the README and quick looks, SVG for
// reports that zoom. The format follows the file's extension. Private to render/.
#include <cairo.h>

#include <functional>
#include <string>

#include "rigdesign/render/palette.hpp"

namespace rigdesign::render {

/// Draws `draw` on a width x height canvas (units: pixels, origin top left) and writes it to
/// `path` (.png or .svg) atomically.
void draw_to_file(const std::string& path, int width, int height,
                  const std::function<void(cairo_t*)>& draw);

/// Encodes an image surface as PNG and writes it to `path` atomically; the caller keeps the
/// surface. Throws std::runtime_error when cairo cannot encode it.
void write_surface_png(cairo_surface_t* surface, const std::string& path);

void set_colour(cairo_t* cairo, const Rgb& colour, double alpha = 1.0);

enum class Anchor { left, centre, right };
/// Text with its baseline at y, anchored horizontally at x.
void draw_text(cairo_t* cairo, const std::string& text, double x, double y, double size,
               Anchor anchor = Anchor::left, bool bold = false);

}  // namespace rigdesign::render
