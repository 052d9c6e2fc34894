#include "rigdesign/render/view_3d_figure.hpp"

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "cairo_canvas.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/render/png_writer.hpp"

namespace rigdesign::render {
namespace {

// The rendered RGBA pixels as a Cairo image (premultiplied BGRA in native words; the view is
// opaque, so no premultiplication is needed).
using Surface = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
Surface image_of(const std::vector<std::uint8_t>& rgba, int width, int height) {
  Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height),
                  cairo_surface_destroy);
  cairo_surface_flush(surface.get());
  unsigned char* data = cairo_image_surface_get_data(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  for (int y = 0; y < height; ++y) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
    for (int x = 0; x < width; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 4;
      row[x] = (std::uint32_t{rgba[i]} << 16) | (std::uint32_t{rgba[i + 1]} << 8) | rgba[i + 2];
    }
  }
  cairo_surface_mark_dirty(surface.get());
  return surface;
}

// A white box behind text so it reads over the coloured volumes.
void halo_text(cairo_t* cairo, const std::string& text, double x, double y, double size,
               const Rgb& colour, bool bold = false) {
  const double width = 0.62 * size * static_cast<double>(text.size());
  cairo_set_source_rgba(cairo, 1, 1, 1, 0.8);
  cairo_rectangle(cairo, x - 3, y - size, width + 6, size + 5);
  cairo_fill(cairo);
  set_colour(cairo, colour);
  draw_text(cairo, text, x, y, size, Anchor::left, bold);
}

// The longest of 0.25, 0.5, 1, 2, 5 m that fits in a fifth of the image.
double scale_bar_metres(double pixels_per_metre, int width) {
  double best = 0.25;
  for (const double metres : {0.25, 0.5, 1.0, 2.0, 5.0, 10.0}) {
    if (metres * pixels_per_metre <= width / 5.0) best = metres;
  }
  return best;
}

// Labels beside their dots, moved down or to the other side until no two overlap (mounts
// close together in the image, as a front camera over a side one, would print over each
// other); a leader line joins a moved label to its dot. The dots go last, so no label hides
// where a sensor is.
void draw_view_labels(cairo_t* cairo, const ViewProjection& projection,
                      const std::vector<ViewLabel>& labels) {
  struct Box {
    double left, top, right, bottom;
    bool overlaps(const Box& other) const {
      return left < other.right && other.left < right && top < other.bottom && other.top < bottom;
    }
  };
  std::vector<Box> placed;
  for (const ViewLabel& label : labels) {
    const auto [x, y] = projection.pixel(label.at);
    const double text_width = 0.62 * 13 * static_cast<double>(label.text.size()) + 6;
    Box box{};
    double text_x = x + 9, text_y = y - 6;
    for (int attempt = 0; attempt < 24; ++attempt) {
      const bool left_side = attempt % 2 == 1;
      text_x = left_side ? x - 9 - text_width : x + 9;
      text_y = y - 6 + 17.0 * (attempt / 2);
      box = Box{text_x - 3, text_y - 13, text_x + text_width, text_y + 5};
      bool free = true;
      for (const Box& other : placed) free = free && !box.overlaps(other);
      if (free) break;
    }
    placed.push_back(box);
    set_colour(cairo, kInkColour, 0.6);
    cairo_set_line_width(cairo, 1);
    cairo_move_to(cairo, x, y);
    cairo_line_to(cairo, text_x < x ? box.right : box.left, text_y - 4);
    cairo_stroke(cairo);
    halo_text(cairo, label.text, text_x, text_y, 13, kInkColour, true);
  }
  for (const ViewLabel& label : labels) {
    const auto [x, y] = projection.pixel(label.at);
    set_colour(cairo, label.colour);
    cairo_arc(cairo, x, y, 5, 0, 2 * std::numbers::pi);
    cairo_fill_preserve(cairo);
    set_colour(cairo, kInkColour);
    cairo_set_line_width(cairo, 1);
    cairo_stroke(cairo);
  }
}

// Legend, top left: each sensor's colour, the body's, and what the floor grid and the axis
// arrows mean.
void draw_view_legend(cairo_t* cairo, const ViewProjection& projection,
                      const std::vector<LegendEntry>& legend) {
  double y = 84;
  set_colour(cairo, kInkColour);
  draw_text(cairo, "sensor (volume it sees, to d)", 20, y, 13, Anchor::left, true);
  for (const LegendEntry& entry : legend) {
    y += 21;
    set_colour(cairo, entry.colour, 0.7);
    cairo_rectangle(cairo, 20, y - 12, 24, 14);
    cairo_fill(cairo);
    set_colour(cairo, kInkColour);
    draw_text(cairo, entry.text, 52, y, 13);
  }
  y += 21;
  set_colour(cairo, kBodyColour);
  cairo_rectangle(cairo, 20, y - 12, 24, 14);
  cairo_fill(cairo);
  set_colour(cairo, kInkColour);
  draw_text(cairo, "robot body", 52, y, 13);
  y += 21;
  draw_text(cairo,
            "floor grid: " + model::format_number(projection.grid_spacing) +
                " m squares; axes x red (forward), y green (left), z blue (up)",
            20, y, 12);
}

// Scale bar, bottom left: a length along the image's x axis, horizontal in the robot frame.
void draw_view_scale_bar(cairo_t* cairo, const ViewProjection& projection,
                         const View3dSettings& settings) {
  const double metres = scale_bar_metres(projection.pixels_per_metre(), settings.width);
  const double length = metres * projection.pixels_per_metre();
  const double bar_y = settings.height - 30;
  set_colour(cairo, kInkColour);
  cairo_set_line_width(cairo, 3);
  cairo_move_to(cairo, 30, bar_y);
  cairo_line_to(cairo, 30 + length, bar_y);
  cairo_stroke(cairo);
  cairo_set_line_width(cairo, 1.5);
  for (const double x : {30.0, 30.0 + length}) {
    cairo_move_to(cairo, x, bar_y - 6);
    cairo_line_to(cairo, x, bar_y + 6);
    cairo_stroke(cairo);
  }
  draw_text(cairo, model::format_number(metres) + " m", 30 + length / 2, bar_y - 10, 13,
            Anchor::centre, true);
  draw_text(cairo, "(orthographic: lengths across the image)", 40 + length, bar_y + 5, 11);
}

void draw_overlay(cairo_t* cairo, const ViewProjection& projection, const View3dOverlay& overlay,
                  const View3dSettings& settings) {
  const double width = settings.width;
  set_colour(cairo, kInkColour);
  draw_text(cairo, overlay.title, width / 2, 32, 20, Anchor::centre, true);
  if (!overlay.subtitle.empty()) {
    draw_text(cairo, overlay.subtitle, width / 2, 54, 13, Anchor::centre);
  }
  draw_view_labels(cairo, projection, overlay.labels);
  draw_view_legend(cairo, projection, overlay.legend);
  draw_view_scale_bar(cairo, projection, settings);
}

}  // namespace

void render_view_3d(const std::vector<ColouredMesh>& meshes, const View3dSettings& settings,
                    const View3dOverlay& overlay, const std::string& path) {
  const std::vector<std::uint8_t> pixels = render_view_3d_pixels(meshes, settings);
  const ViewProjection projection = view_projection(meshes, settings);
  const Surface image = image_of(pixels, settings.width, settings.height);
  draw_to_file(path, settings.width, settings.height, [&](cairo_t* cairo) {
    cairo_set_source_surface(cairo, image.get(), 0, 0);
    cairo_paint(cairo);
    draw_overlay(cairo, projection, overlay, settings);
  });
}

void render_view_3d(const std::vector<ColouredMesh>& meshes, const View3dSettings& settings,
                    const std::string& png_path) {
  write_png_rgba(png_path, settings.width, settings.height,
                 render_view_3d_pixels(meshes, settings));
}

}  // namespace rigdesign::render
