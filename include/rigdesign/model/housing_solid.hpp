#pragma once
/// A sensor's housing from its datasheet (issue 52 item 2): one simple solid, a box or a
/// cylinder, placed in the sensor frame (origin at the data origin, x forward, y left, z up).
/// Housings make a rig buildable: each is solid for every other sensor, and no two may
/// overlap each other or the robot's body. A cylinder's axis is the sensor frame's z.
#include <string>

#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/name_table.hpp"
#include "rigdesign/model/source_location.hpp"

namespace rigdesign::model {

enum class HousingShape { box, cylinder };
inline constexpr NameTable<HousingShape, 2> kHousingShapeNames = {{
    {HousingShape::box, "box"},
    {HousingShape::cylinder, "cylinder"},
}};
static_assert(covers_in_order(kHousingShapeNames) &&
              kHousingShapeNames.size() == static_cast<std::size_t>(HousingShape::cylinder) + 1);

/// Which point of a sensor a catalog slot's pose places (issue 52): its data origin, or the
/// centre of its housing's bottom face (a sensor standing on a plate) or back face (one against
/// a wall), so that every sensor the slot allows stands on the body whatever its housing.
enum class HousingSeat { origin, bottom, back };
inline constexpr NameTable<HousingSeat, 3> kHousingSeatNames = {{
    {HousingSeat::origin, "origin"},
    {HousingSeat::bottom, "bottom"},
    {HousingSeat::back, "back"},
}};
static_assert(covers_in_order(kHousingSeatNames) &&
              kHousingSeatNames.size() == static_cast<std::size_t>(HousingSeat::back) + 1);

struct HousingSolid {
  HousingShape shape = HousingShape::box;
  /// [m] a box's full lengths along the sensor frame's x, y, z; a cylinder's (2 r, 2 r, height).
  Vec3 size = Vec3::Zero();
  Vec3 center = Vec3::Zero();  ///< [m] the solid's centre in the sensor frame
  std::string source;          ///< where the dimensions and the data origin's place come from
  SourceLocation where;

  double radius() const { return 0.5 * size.x(); }
  /// The seat's point in the sensor frame [m]: the origin, or the centre of the bottom (-z)
  /// or back (-x) face.
  Vec3 seat(HousingSeat at) const {
    if (at == HousingSeat::bottom) return center - Vec3(0, 0, 0.5 * size.z());
    if (at == HousingSeat::back) return center - Vec3(0.5 * size.x(), 0, 0);
    return Vec3::Zero();
  }
};

}  // namespace rigdesign::model
