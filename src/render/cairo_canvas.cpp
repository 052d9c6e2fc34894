#include "cairo_canvas.hpp"

#include <cairo-svg.h>

#include <memory>
#include <stdexcept>

#include "rigdesign/io/atomic_write.hpp"

namespace rigdesign::render {
namespace {

cairo_status_t append_to_string(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

void paint(cairo_surface_t* surface, const std::function<void(cairo_t*)>& draw) {
  cairo_t* cairo = cairo_create(surface);
  cairo_set_source_rgb(cairo, 1, 1, 1);
  cairo_paint(cairo);
  draw(cairo);
  const cairo_status_t status = cairo_status(cairo);
  cairo_destroy(cairo);
  if (status != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(std::string("drawing failed: ") + cairo_status_to_string(status));
  }
}

}  // namespace

void draw_to_file(const std::string& path, int width, int height,
                  const std::function<void(cairo_t*)>& draw) {
  // Destroyed on every path, a throwing `draw` included.
  using Surface = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
  if (ends_with(path, ".svg")) {
    std::string bytes;
    {
      const Surface surface(
          cairo_svg_surface_create_for_stream(append_to_string, &bytes, width, height),
          cairo_surface_destroy);
      paint(surface.get(), draw);
      cairo_surface_finish(surface.get());
    }
    io::write_file_atomically(path, bytes);
    return;
  }
  const Surface surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height),
                        cairo_surface_destroy);
  paint(surface.get(), draw);
  write_surface_png(surface.get(), path);
}

void write_surface_png(cairo_surface_t* surface, const std::string& path) {
  std::string bytes;
  const cairo_status_t status =
      cairo_surface_write_to_png_stream(surface, append_to_string, &bytes);
  if (status != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(std::string("PNG encoding failed: ") + cairo_status_to_string(status));
  }
  io::write_file_atomically(path, bytes);
}

void set_colour(cairo_t* cairo, const Rgb& colour, double alpha) {
  cairo_set_source_rgba(cairo, colour.r, colour.g, colour.b, alpha);
}

void draw_text(cairo_t* cairo, const std::string& text, double x, double y, double size,
               Anchor anchor, bool bold) {
  cairo_select_font_face(cairo, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cairo, size);
  cairo_text_extents_t extents;
  cairo_text_extents(cairo, text.c_str(), &extents);
  double left = x;
  if (anchor == Anchor::centre) left = x - extents.x_advance / 2;
  if (anchor == Anchor::right) left = x - extents.x_advance;
  cairo_move_to(cairo, left, y);
  cairo_show_text(cairo, text.c_str());
  cairo_new_path(cairo);  // no current point left behind for the next arc or line
}

}  // namespace rigdesign::render
