#include "rigdesign/deploy/self_filters.hpp"

#include <algorithm>
#include <cmath>

#include "rigdesign/geometry/body_mesh.hpp"
#include "rigdesign/geometry/body_occluder.hpp"
#include "rigdesign/geometry/solid_shadow.hpp"
#include "rigdesign/sim/decimation.hpp"
#include "rigdesign/sim/ray_caster.hpp"
#include "rigdesign/sim/sensor_simulator.hpp"

namespace rigdesign::deploy {
namespace {

// The body as separately cast parts: a description's links, or the cylinder or prism whole.
struct CastPart {
  std::string name;
  const model::BodyPart* part = nullptr;  // null for a cylinder or prism body
  sim::RayCaster caster;
};

std::vector<CastPart> cast_parts(const model::RobotBody& body) {
  std::vector<CastPart> parts;
  if (!body.has_parts()) {
    parts.push_back({"body", nullptr, sim::RayCaster(geometry::body_mesh(body))});
    return parts;
  }
  for (const model::BodyPart& part : body.parts) {
    model::RobotBody alone;
    alone.parts = {part};
    parts.push_back({part.link, &part, sim::RayCaster(geometry::body_mesh(alone))});
  }
  return parts;
}

// Scan angles of the hit rays as bands reaching halfway to their unhit neighbours.
std::vector<model::AzimuthBand> bands_of(std::vector<std::pair<double, bool>> rays, double step) {
  std::sort(rays.begin(), rays.end());
  std::vector<model::AzimuthBand> bands;
  for (std::size_t i = 0; i < rays.size();) {
    if (!rays[i].second) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < rays.size() && rays[j + 1].second) ++j;
    // Half a step beyond the hit rays; a run at either end of the scan reaches past +-pi so
    // that the filter, which drops angles strictly inside its bounds, also drops the end ray.
    bands.push_back({rays[i].first - step / 2, rays[j].first + step / 2});
    i = j + 1;
  }
  return bands;
}

}  // namespace

std::vector<SelfFilter> self_filters(const model::Rig& rig, const model::SensorLibrary& library,
                                     const SelfFilterSettings& settings) {
  const std::vector<CastPart> parts = cast_parts(rig.body);
  const geometry::BodyOccluder occluder(rig.body);
  std::vector<SelfFilter> filters;
  for (const model::Mount& mount : rig.mounts) {
    const model::SensorMode mode =
        sim::decimated_mode(library.resolved_mode(mount.sensor_id, mount.mode_id),
                            settings.camera_decimation, settings.lidar_decimation);
    const model::Vec3 origin = mount.T_robot_sensor.translation();
    const model::Mat3 R = mount.T_robot_sensor.linear();
    SelfFilter filter;
    filter.mount_id = mount.id;
    filter.scanner = mode.fov.shape().is_planar_scan();
    std::vector<bool> housing(parts.size());
    for (std::size_t k = 0; k < parts.size(); ++k) {
      housing[k] =
          parts[k].part ? geometry::inside_part(*parts[k].part, origin) : occluder.contains(origin);
    }
    std::vector<std::pair<double, bool>> scan;
    std::vector<SelfBox> boxes(parts.size());
    double largest_noise = 0.0;
    for (const model::Vec3& ray : sim::ray_pattern(mode)) {
      ++filter.rays;
      const model::Vec3 direction = R * ray;
      double nearest = mode.max_range;
      int hit_part = -1;
      for (std::size_t k = 0; k < parts.size(); ++k) {
        if (housing[k]) continue;
        const std::optional<double> t = parts[k].caster.first_hit(origin, direction);
        if (t && *t >= mode.min_range && *t <= nearest) {
          nearest = *t;
          hit_part = static_cast<int>(k);
        }
      }
      if (filter.scanner) scan.emplace_back(std::atan2(ray.y(), ray.x()), hit_part >= 0);
      if (hit_part < 0) continue;
      ++filter.body_hits;
      largest_noise = std::max(largest_noise, mode.noise.sigma(nearest));
      const model::Vec3 hit = origin + nearest * direction;
      SelfBox& box = boxes[hit_part];
      box.min = box.hits == 0 ? hit : model::Vec3(box.min.cwiseMin(hit));
      box.max = box.hits == 0 ? hit : model::Vec3(box.max.cwiseMax(hit));
      ++box.hits;
    }
    filter.padding = 3 * largest_noise;
    if (filter.scanner) {
      filter.bands = bands_of(std::move(scan), mode.angular_resolution_h);
    } else {
      for (std::size_t k = 0; k < parts.size(); ++k) {
        if (boxes[k].hits == 0) continue;
        SelfBox box = boxes[k];
        box.part = parts[k].name;
        box.min -= model::Vec3::Constant(filter.padding);
        box.max += model::Vec3::Constant(filter.padding);
        filter.boxes.push_back(box);
      }
    }
    filters.push_back(std::move(filter));
  }
  return filters;
}

}  // namespace rigdesign::deploy
