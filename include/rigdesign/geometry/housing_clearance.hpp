#pragma once
/// Whether a mount's housing (model::HousingSolid) can be bolted where the rig puts it (issue
/// 52 item 2): it must not cut into the robot body (but for the description link that is the
/// sensor's own housing) or into another mount's housing. Touching is allowed: a clash is an
/// overlap deeper than kHousingTouch (between housings, the least translation that would part
/// the two convex solids; into the body, see body_clashes).
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/geometry/housing_geometry.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"
#include "rigdesign/model/source_location.hpp"

namespace rigdesign::geometry {

/// [m] overlap allowed between solids that touch: paint, a gasket, a rounded datasheet figure.
inline constexpr double kHousingTouch = 0.001;
/// [m] a gap a washer or shim takes up: a housing this close to what holds it is held.
inline constexpr double kHousingShim = 0.005;

/// Whether two convex solids (housings, supports) cut into each other deeper than
/// kHousingTouch: the one overlap rule of B2 and of select's search.
bool solids_clash(const ConvexSolid& a, const ConvexSolid& b);

/// What a housing cuts into.
struct HousingClash {
  std::string link;        ///< the body part's link (empty: a cylinder or prism body)
  std::string mount_id;    ///< or another mount, whose housing it overlaps
  std::string support_id;  ///< or a support of the rig
  model::SourceLocation where;
  double depth = 0.0;  ///< [m] how far the solids interpenetrate
  /// "cuts 12 mm into the collision geometry of link 'chassis_link' (jackal.urdf.xacro:111)".
  std::string describe() const;
  /// "the collision geometry of link 'chassis_link' (jackal.urdf.xacro:111)".
  std::string what() const;
};

/// Where `housing`, placed by `T_robot_sensor`, cuts into `robot`'s body, but for the parts of
/// the link `housing_link` (the sensor's own housing in the description; empty: none). The
/// depth into a solid is the largest inset at which the housing, shrunk by it on every side,
/// still meets the solid (crosses a face of it, or lies inside it).
std::vector<HousingClash> body_clashes(const model::DescribedRobot& robot,
                                       const std::string& housing_link,
                                       const model::HousingSolid& housing,
                                       const model::Pose3& T_robot_sensor);

/// How far mount `index`'s housing floats [m]: the least growth on every side at which it
/// meets the body, a description link or another housing (a rough distance: a box grown at
/// its corners reaches up to sqrt(3) times as far). Nothing when one is within kHousingShim, it
/// sits on a description link of its own, or it has no housing; 0.5 m when nothing is that
/// close.
std::optional<double> housing_gap(const model::Rig& rig, const model::SensorLibrary& library,
                                  std::size_t index);

/// Every clash of mount `index`'s housing, body parts first, then the other mounts' housings in
/// rig order; empty when its sensor has no housing. Deterministic.
std::vector<HousingClash> housing_clashes(const model::Rig& rig,
                                          const model::SensorLibrary& library, std::size_t index);

}  // namespace rigdesign::geometry
