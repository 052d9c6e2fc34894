#include "rigdesign/render/palette.hpp"

namespace rigdesign {

Rgb sensor_colour(std::size_t index) {
  // Okabe-Ito colour-blind-safe palette (without black), then repeated.
  static constexpr std::array<Rgb, 7> kPalette = {{{0.90, 0.62, 0.00},
                                                   {0.34, 0.71, 0.91},
                                                   {0.00, 0.62, 0.45},
                                                   {0.80, 0.47, 0.65},
                                                   {0.00, 0.45, 0.70},
                                                   {0.84, 0.37, 0.00},
                                                   {0.94, 0.89, 0.26}}};
  return kPalette[index % kPalette.size()];
}

}  // namespace rigdesign
