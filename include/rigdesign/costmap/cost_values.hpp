#pragma once
/// Cost values of a 2D costmap cell, as nav2's costmap_2d defines them (cost_values.hpp), so
/// grids, thresholds and exports compare one to one with a nav2 stack.
#include <cstdint>

namespace rigdesign::costmap::cost {

constexpr std::uint8_t kFree = 0;              ///< FREE_SPACE
constexpr std::uint8_t kMaxNonObstacle = 252;  ///< MAX_NON_OBSTACLE: the top of the decaying range
constexpr std::uint8_t kInscribed = 253;  ///< INSCRIBED_INFLATED_OBSTACLE: the centre here collides
constexpr std::uint8_t kLethal = 254;     ///< LETHAL_OBSTACLE: an obstacle in the cell
constexpr std::uint8_t kUnknown = 255;    ///< NO_INFORMATION

}  // namespace rigdesign::costmap::cost
