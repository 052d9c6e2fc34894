#include "rigdesign/metrics/sector_blame.hpp"

#include "rigdesign/geometry/body_occluder.hpp"
#include "rigdesign/geometry/cross_section.hpp"
#include "rigdesign/geometry/housing_geometry.hpp"
#include "rigdesign/geometry/mounted_fov.hpp"
#include "rigdesign/geometry/section_polygons.hpp"

namespace rigdesign::metrics {
namespace {

// Shares below this differ only by the exact path's rounding.
constexpr double kBlameEpsilon = 1e-6;

// The mount's own share of `frame` seen past `occluder` and the housings `around` it (SC
// floor or SC complete).
double mount_share(const model::Mount& mount, const model::SensorMode& mode,
                   const geometry::BodyOccluder& occluder, const geometry::SectionFrame& frame,
                   bool floor, const std::vector<model::BodyPart>& around = {}) {
  const geometry::MountedFov fov(mode, mount.T_robot_sensor, occluder, mount.housing_link,
                                 mount.limits, around);
  if (floor) return geometry::floor_coverage(fov, frame).length() / frame.width();
  return geometry::union_area({geometry::section_polygons(fov, frame, {})}) / frame.area();
}

}  // namespace

SectorBlame sector_blame(const model::Rig& rig, const model::SensorLibrary& library, double theta,
                         bool floor) {
  SectorBlame blame;
  const geometry::BodyOccluder body(rig.body);
  const model::RobotBody none;  // the occluder keeps a pointer into the body it is given
  const geometry::BodyOccluder transparent(none);
  const geometry::SectionFrame frame =
      geometry::section_frame(body, theta, rig.distance_of_interest);
  if (frame.width() <= 0) return blame;
  double best_open = 0.0;
  double best_seen = 0.0;
  for (std::size_t m = 0; m < rig.mounts.size(); ++m) {
    const model::Mount& mount = rig.mounts[m];
    const model::SensorMode& mode = library.resolved_mode(mount.sensor_id, mount.mode_id);
    const double open = mount_share(mount, mode, transparent, frame, floor);
    if (open <= best_open + kBlameEpsilon) continue;
    best_open = open;
    best_seen = mount_share(mount, mode, body, frame, floor,
                            geometry::housings_around(rig, library, mount.id));
    blame.mount = m;
  }
  if (!blame.mount) return blame;
  const model::Mount& mount = rig.mounts[*blame.mount];
  blame.where = mount.pose_where.file.empty() ? mount.where : mount.pose_where;
  blame.hidden = best_open - best_seen;
  if (blame.hidden <= kBlameEpsilon) return blame;
  blame.body = true;
  blame.where = rig.body.where;
  // A description's part or another sensor's housing: the one that alone hides most of it.
  const model::SensorMode& mode = library.resolved_mode(mount.sensor_id, mount.mode_id);
  double most = kBlameEpsilon;
  const auto hidden_by = [&](const model::BodyPart& part, bool housing) {
    if (housing) return best_open - mount_share(mount, mode, transparent, frame, floor, {part});
    model::RobotBody alone = rig.body;
    alone.parts = {part};
    return best_open - mount_share(mount, mode, geometry::BodyOccluder(alone), frame, floor);
  };
  const auto try_part = [&](const model::BodyPart& part, bool housing) {
    const double hidden = hidden_by(part, housing);
    if (hidden > most) {
      most = hidden;
      blame.part = part.link;
      blame.where = part.where;
      blame.by_housing = housing;
    }
  };
  for (const model::BodyPart& part : rig.body.parts) try_part(part, false);
  for (const model::BodyPart& part : geometry::housings_around(rig, library, mount.id))
    try_part(part, true);
  return blame;
}

}  // namespace rigdesign::metrics
