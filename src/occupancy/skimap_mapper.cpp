// SkiMap's weighted voxel map for paper 3's comparison; the method is in skimap_mapper.hpp.
#include "rigdesign/occupancy/skimap_mapper.hpp"

#include <map>
#include <stdexcept>

#include "rigdesign/model/format_number.hpp"

namespace rigdesign::occupancy {
namespace {

class SkiMapMapper final : public OccupancyMapper {
 public:
  explicit SkiMapMapper(const SkiMapParams& params) : params_(params) {}

  std::string name() const override { return skimap_label(params_); }

  VoxelLattice lattice() const override {
    return {params_.voxel, params_.voxel, 0.0, params_.z_max};
  }

  // Every point adds 1 to its voxel (skimap_ros integrates each point with weight 1).
  void update(double, std::span<const model::PointCloud> clouds, bool) override {
    const VoxelLattice grid = lattice();
    for (const model::PointCloud& cloud : clouds) {
      for (const model::Point3f& p : cloud.points) {
        if (p.z() < params_.min_height || p.z() >= params_.z_max) continue;
        weights_[grid.key_at(p.cast<double>())] += 1.0;
      }
    }
  }

  std::vector<costmap::VoxelKey> occupied() const override {
    std::vector<costmap::VoxelKey> keys;
    for (const auto& [key, weight] : weights_) {
      if (weight >= params_.min_voxel_weight) keys.push_back(key);
    }
    return keys;  // the map's order: ascending
  }

  // The stand-in's storage: a red-black tree node per voxel (libstdc++: colour and three
  // pointers, 32 bytes, before the key and weight). SkiMap's skip lists differ in layout.
  std::size_t memory_bytes() const override {
    return weights_.size() * (32 + sizeof(std::pair<const costmap::VoxelKey, double>));
  }

 private:
  SkiMapParams params_;
  std::map<costmap::VoxelKey, double> weights_;
};

}  // namespace

std::string skimap_label(const SkiMapParams& params) {
  return "SkiMap " + model::format_number(params.voxel, 3) + " m, min weight " +
         model::format_number(params.min_voxel_weight, 3);
}

std::unique_ptr<OccupancyMapper> make_skimap_mapper(const SkiMapParams& params) {
  if (!(params.voxel >= 0.01 && params.voxel <= 1.0))
    throw std::invalid_argument("SkiMap: voxel must lie in [0.01, 1] m");
  if (!(params.min_voxel_weight >= 1.0))
    throw std::invalid_argument("SkiMap: min_voxel_weight must be at least 1");
  if (!(params.z_max > params.min_height))
    throw std::invalid_argument("SkiMap: z_max must exceed min_height");
  return std::make_unique<SkiMapMapper>(params);
}

}  // namespace rigdesign::occupancy
