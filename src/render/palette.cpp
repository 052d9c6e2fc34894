#include "rigdesign/render/palette.hpp"

namespace rigdesign::render {

Rgb sensor_colour(std::size_t index) {
  // Okabe-Ito colour-blind-safe palette (without black), ordered so that neighbours differ
  // in hue and lightness; repeats after seven sensors.
  static constexpr std::array<Rgb, 7> kPalette = {{{0.90, 0.62, 0.00},    // orange
                                                   {0.00, 0.45, 0.70},    // blue
                                                   {0.00, 0.62, 0.45},    // bluish green
                                                   {0.84, 0.37, 0.00},    // vermillion
                                                   {0.80, 0.47, 0.65},    // reddish purple
                                                   {0.34, 0.71, 0.91},    // sky blue
                                                   {0.94, 0.89, 0.26}}};  // yellow
  return kPalette[index % kPalette.size()];
}

}  // namespace rigdesign::render
