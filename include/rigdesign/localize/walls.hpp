#pragma once
/// Walls in the horizontal plane and the attenuation a radio path suffers crossing them: the
/// scenarios' layouts, and a map the range fit can use (`localize --walls FILE`): a wall on
/// one side of a straight path tells mirror-image hypotheses apart.
#include <vector>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::localize {

struct WallSegment {
  model::Vec2 a, b;       ///< end points in the horizontal plane [m]
  double attenuation_db;  ///< loss when the line of sight crosses it [dB]
};

/// Total attenuation of the walls crossed by the segment from `from` to `to` (x, y only) [dB].
/// A path parallel to a wall does not cross it.
double wall_loss_db(const std::vector<WallSegment>& walls, const model::Vec3& from,
                    const model::Vec3& to);
double wall_loss_db(const std::vector<WallSegment>& walls, const model::Vec2& from,
                    const model::Vec2& to);

}  // namespace rigdesign::localize
