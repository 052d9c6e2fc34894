#pragma once
/// Colours shared by every picture, so a sensor has the same colour in the SC plots, the
/// cross-sections and the 3D view.
#include <array>
#include <cstddef>

namespace rigdesign::render {

struct Rgb {
  double r = 0.0;  ///< [0, 1]
  double g = 0.0;
  double b = 0.0;
};

/// Colour of the i-th mounted sensor (a qualitative palette, distinguishable in print).
Rgb sensor_colour(std::size_t index);

inline constexpr Rgb kBodyColour{0.55, 0.55, 0.58};
inline constexpr Rgb kCompleteColour{0.12, 0.35, 0.75};
inline constexpr Rgb kFloorColour{0.85, 0.40, 0.05};
inline constexpr Rgb kInkColour{0.15, 0.15, 0.15};   ///< text, axes, frames
inline constexpr Rgb kGridColour{0.87, 0.87, 0.87};  ///< chart grid lines

}  // namespace rigdesign::render
