#include "rigdesign/metrics/sector_blame.hpp"

#include "rigdesign/geometry/body_occluder.hpp"
#include "rigdesign/geometry/cross_section.hpp"
#include "rigdesign/geometry/mounted_fov.hpp"
#include "rigdesign/geometry/section_polygons.hpp"

namespace rigdesign::metrics {
namespace {

// Shares below this differ only by the exact path's rounding.
constexpr double kBlameEpsilon = 1e-6;

// The mount's own share of `frame` seen through `occluder` (SC floor or SC complete).
double mount_share(const model::Mount& mount, const model::SensorMode& mode,
                   const geometry::BodyOccluder& occluder, const geometry::SectionFrame& frame,
                   bool floor) {
  const geometry::MountedFov fov(mode, mount.T_robot_sensor, occluder, mount.housing_link,
                                 mount.limits);
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
    best_seen = mount_share(mount, mode, body, frame, floor);
    blame.mount = m;
  }
  if (!blame.mount) return blame;
  const model::Mount& mount = rig.mounts[*blame.mount];
  blame.where = mount.pose_where.file.empty() ? mount.where : mount.pose_where;
  blame.hidden = best_open - best_seen;
  if (blame.hidden <= kBlameEpsilon) return blame;
  blame.body = true;
  blame.where = rig.body.where;
  // A description's body: the part that alone hides most of that view.
  const model::SensorMode& mode = library.resolved_mode(mount.sensor_id, mount.mode_id);
  double most = kBlameEpsilon;
  for (const model::BodyPart& part : rig.body.parts) {
    model::RobotBody alone = rig.body;
    alone.parts = {part};
    const double hidden =
        best_open - mount_share(mount, mode, geometry::BodyOccluder(alone), frame, floor);
    if (hidden > most) {
      most = hidden;
      blame.part = part.link;
      blame.where = part.where;
    }
  }
  return blame;
}

}  // namespace rigdesign::metrics
