// Voxblox's projective TSDF with the merged integrator, for paper 3's comparison; the method
// is in voxblox_mapper.hpp, taken from Voxblox's paper and documentation.
#include "rigdesign/occupancy/voxblox_mapper.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rigdesign/costmap/grid_traversal.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::occupancy {
namespace {

// A lattice key packed into one integer: 21 bits per axis covers +-10 km at 1 cm voxels.
std::int64_t packed(const costmap::VoxelKey& key) {
  const auto field = [](int v) { return static_cast<std::int64_t>(v + (1 << 20)) & 0x1FFFFF; };
  return (field(key.x) << 42) | (field(key.y) << 21) | field(key.z);
}

void check_voxblox_params(const VoxbloxParams& p) {
  if (!(p.voxel >= 0.01 && p.voxel <= 1.0))
    throw std::invalid_argument("Voxblox: voxel must lie in [0.01, 1] m");
  if (!(p.truncation > 0.0 && p.truncation <= 2.0))
    throw std::invalid_argument("Voxblox: truncation must lie in (0, 2] m");
  if (!(p.max_weight > 0.0)) throw std::invalid_argument("Voxblox: max_weight must be positive");
  if (!(p.min_ray_length >= 0.0 && p.max_ray_length > p.min_ray_length))
    throw std::invalid_argument("Voxblox: need 0 <= min_ray_length < max_ray_length");
  if (!(p.window_size > 0.0 && p.z_max > p.min_height))
    throw std::invalid_argument("Voxblox: need a positive window and z_max above min_height");
}

const VoxbloxParams& checked(const VoxbloxParams& params) {
  check_voxblox_params(params);
  return params;
}

class VoxbloxMapper final : public OccupancyMapper {
 public:
  VoxbloxMapper(const VoxbloxParams& params, std::vector<DepthAxis> depth_axes)
      : tsdf_(params), depth_axes_(std::move(depth_axes)) {}

  std::string name() const override { return voxblox_label(tsdf_.params()); }

  VoxelLattice lattice() const override {
    return {tsdf_.params().voxel, tsdf_.params().voxel, 0.0, tsdf_.params().z_max};
  }

  void update(double, std::span<const model::PointCloud> clouds, bool) override {
    if (clouds.size() != depth_axes_.size())
      throw std::invalid_argument("Voxblox: one depth axis per cloud is needed");
    for (std::size_t i = 0; i < clouds.size(); ++i) tsdf_.integrate(clouds[i], depth_axes_[i]);
  }

  std::vector<costmap::VoxelKey> occupied() const override { return tsdf_.occupied(); }

  std::size_t memory_bytes() const override { return tsdf_.memory_bytes(); }

 private:
  VoxbloxTsdf tsdf_;
  std::vector<DepthAxis> depth_axes_;
};

}  // namespace

VoxbloxTsdf::VoxbloxTsdf(const VoxbloxParams& params)
    : params_(checked(params)),
      window_(centred_window(params.window_size, params.voxel)),
      layers_(std::max(1, static_cast<int>(std::ceil(params.z_max / params.voxel - 1e-9)))),
      size_(window_.width, window_.height, layers_),
      // z fastest, then x, then y (as the voxel layer lays its columns out).
      stride_(layers_, static_cast<std::ptrdiff_t>(window_.width) * layers_, 1),
      corner_(window_.origin_cell.x() * params.voxel, window_.origin_cell.y() * params.voxel, 0.0),
      distance_(static_cast<std::size_t>(window_.width) * window_.height * layers_, 0.0f),
      weight_(distance_.size(), 0.0f) {}

VoxbloxTsdf::Voxel VoxbloxTsdf::at(const costmap::VoxelKey& key) const {
  const int x = key.x - window_.origin_cell.x(), y = key.y - window_.origin_cell.y();
  if (x < 0 || y < 0 || key.z < 0 || x >= size_.x() || y >= size_.y() || key.z >= layers_)
    return {};
  const auto i = static_cast<std::size_t>(key.z + x * stride_[0] + y * stride_[1]);
  return {distance_[i], weight_[i]};
}

std::vector<costmap::VoxelKey> VoxbloxTsdf::occupied() const {
  // Both rules compare Voxblox's float voxels with float thresholds, as ptcloud_vis.h does.
  const bool nodes = params_.occupied_rule == VoxbloxOccupiedRule::occupied_nodes;
  const float min_weight = nodes ? 1e-3f : 0.0f;
  const auto voxel = static_cast<float>(params_.voxel);
  const float surface = 0.75f * voxel;
  const auto shown = [&](float distance) {
    return nodes ? distance <= voxel : std::abs(distance) < surface;
  };
  std::vector<costmap::VoxelKey> keys;
  for (int x = 0; x < size_.x(); ++x) {
    for (int y = 0; y < size_.y(); ++y) {
      for (int z = 0; z < layers_; ++z) {
        const auto i = static_cast<std::size_t>(z + x * stride_[0] + y * stride_[1]);
        if (weight_[i] > min_weight && shown(distance_[i])) {
          keys.push_back({window_.origin_cell.x() + x, window_.origin_cell.y() + y, z});
        }
      }
    }
  }
  return keys;  // x, then y, then z ascending: the keys' order
}

double VoxbloxTsdf::point_weight(const model::Vec3& offset,
                                 const Eigen::Quaterniond& R_world_sensor, DepthAxis axis) const {
  if (params_.use_const_weight) return 1.0;
  const model::Vec3 local = R_world_sensor.conjugate() * offset;
  const double z = axis == DepthAxis::optical ? local.x() : local.z();
  return std::abs(z) < 1e-6 ? 0.0 : 1.0 / (z * z);
}

void VoxbloxTsdf::integrate(const model::PointCloud& cloud, DepthAxis axis) {
  const model::Vec3 origin = cloud.origin.cast<double>();
  const Eigen::Quaterniond rotation = cloud.orientation.cast<double>();
  const VoxelLattice grid{params_.voxel, params_.voxel, 0.0, params_.z_max};
  marking_.clear();
  clearing_.clear();
  for (const model::Point3f& point : cloud.points) {
    const model::Vec3 p = point.cast<double>();
    const double range = (p - origin).norm();
    if (range < params_.min_ray_length) continue;
    const double w = point_weight(p - origin, rotation, axis);
    if (w <= 0.0) continue;  // a zero-weight ray changes nothing
    const bool clears = range > params_.max_ray_length || p.z() < params_.min_height;
    MergedRay& ray = (clears ? clearing_ : marking_)[packed(grid.key_at(p))];
    ray.weighted_sum += w * p;
    ray.weight += w;
  }
  for (const auto& [key, ray] : marking_) cast(origin, ray, false);
  for (const auto& [key, ray] : clearing_) cast(origin, ray, true);
}

// One merged ray: from the origin to delta behind its point, or (clearing) to delta before it,
// a clearing ray also ending at max_ray_length.
void VoxbloxTsdf::cast(const model::Vec3& origin, const MergedRay& ray, bool clearing) {
  const double delta = params_.truncation, epsilon = params_.voxel;
  const model::Vec3 point = ray.weighted_sum / ray.weight;
  const double range = (point - origin).norm();
  const model::Vec3 direction = (point - origin) / range;
  const double end =
      clearing ? std::min(std::max(range - delta, 0.0), params_.max_ray_length) : range + delta;
  costmap::detail::GridPoint<3> a = (origin - corner_) / params_.voxel;
  costmap::detail::GridPoint<3> b = (origin + end * direction - corner_) / params_.voxel;
  bool clipped = false;
  if (!costmap::detail::clip_to_grid<3>(a, b, size_, clipped)) return;
  const std::ptrdiff_t per_y = stride_[1], per_x = stride_[0];
  costmap::detail::walk_cells<3>(a, b, size_, stride_, true, [&](std::ptrdiff_t i) {
    const auto y = static_cast<double>(i / per_y);
    const auto x = static_cast<double>((i % per_y) / per_x);
    const auto z = static_cast<double>(i % per_x);
    const model::Vec3 centre = corner_ + model::Vec3(x + 0.5, y + 0.5, z + 0.5) * params_.voxel;
    const double d = range - (centre - origin).dot(direction);
    double w = ray.weight;
    // Full weight up to one voxel behind the surface, falling linearly to 0 at -delta (only
    // where delta exceeds a voxel: otherwise there is no such stretch).
    if (delta > epsilon && d < -epsilon) w *= std::max(0.0, (delta + d) / (delta - epsilon));
    const auto u = static_cast<std::size_t>(i);
    const double total = weight_[u] + w;
    if (total < 1e-6) return;
    const double fused = (distance_[u] * weight_[u] + d * w) / total;
    distance_[u] = static_cast<float>(std::clamp(fused, -delta, delta));
    weight_[u] = static_cast<float>(std::min(total, params_.max_weight));
  });
}

std::string voxblox_label(const VoxbloxParams& params) {
  return "Voxblox " + model::format_number(params.voxel, 3) + " m, trunc " +
         model::format_number(params.truncation, 3) + " m" +
         (params.use_const_weight ? ", const weight" : "") +
         (params.occupied_rule == VoxbloxOccupiedRule::surface_pointcloud ? ", surface" : "");
}

std::unique_ptr<OccupancyMapper> make_voxblox_mapper(const VoxbloxParams& params,
                                                     std::vector<DepthAxis> depth_axes) {
  return std::make_unique<VoxbloxMapper>(params, std::move(depth_axes));
}

}  // namespace rigdesign::occupancy
