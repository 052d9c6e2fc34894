#include "cairo_canvas.hpp"

#include <cairo-svg.h>

#include <cstdio>
#include <memory>
#include <stdexcept>
#include <vector>

#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/io/emit/xml_text.hpp"

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

// Text drawn on an SVG canvas, kept as <text> elements: Cairo's SVG surface would write every
// glyph as a path, and a browser, a search or a test could not read a word of the picture.
struct SvgText {
  std::vector<std::string> elements;
};
cairo_user_data_key_t svg_text_key;

SvgText* svg_text_of(cairo_t* cairo) {
  return static_cast<SvgText*>(cairo_surface_get_user_data(cairo_get_target(cairo), &svg_text_key));
}

std::string svg_text_element(cairo_t* cairo, const std::string& text, double x, double y,
                             double size, Anchor anchor, bool bold) {
  cairo_matrix_t m;
  cairo_get_matrix(cairo, &m);
  double red = 0, green = 0, blue = 0, alpha = 1;
  cairo_pattern_get_rgba(cairo_get_source(cairo), &red, &green, &blue, &alpha);
  const char* text_anchor = anchor == Anchor::centre  ? "middle"
                            : anchor == Anchor::right ? "end"
                                                      : "start";
  char head[512];
  std::snprintf(head, sizeof head,
                "<text transform=\"matrix(%.6g %.6g %.6g %.6g %.6g %.6g)\" x=\"%.6g\" y=\"%.6g\" "
                "font-family=\"DejaVu Sans, sans-serif\" font-size=\"%.6g\"%s "
                "text-anchor=\"%s\" fill=\"rgb(%d,%d,%d)\" fill-opacity=\"%.3g\">",
                m.xx, m.yx, m.xy, m.yy, m.x0, m.y0, x, y, size, bold ? " font-weight=\"bold\"" : "",
                text_anchor, static_cast<int>(red * 255 + 0.5), static_cast<int>(green * 255 + 0.5),
                static_cast<int>(blue * 255 + 0.5), alpha);
  return head + io::xml_escaped(text) + "</text>";
}

}  // namespace

void draw_to_file(const std::string& path, int width, int height,
                  const std::function<void(cairo_t*)>& draw) {
  // Destroyed on every path, a throwing `draw` included.
  using Surface = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
  if (ends_with(path, ".svg")) {
    std::string bytes;
    SvgText text;
    {
      const Surface surface(
          cairo_svg_surface_create_for_stream(append_to_string, &bytes, width, height),
          cairo_surface_destroy);
      cairo_surface_set_user_data(surface.get(), &svg_text_key, &text, nullptr);
      paint(surface.get(), draw);
      cairo_surface_finish(surface.get());
    }
    // Text goes on top of the drawing, as every chart here draws its labels last or on blank
    // ground.
    const std::size_t end = bytes.rfind("</svg>");
    if (end == std::string::npos) throw std::runtime_error("cairo wrote no </svg>: " + path);
    std::string elements;
    for (const std::string& element : text.elements) elements += element + "\n";
    bytes.insert(end, elements);
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
  if (SvgText* svg = svg_text_of(cairo)) {
    svg->elements.push_back(svg_text_element(cairo, text, x, y, size, anchor, bold));
    return;
  }
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
