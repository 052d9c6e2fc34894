// Paper 3's OctoMap: the real library behind the comparison's common mapper interface.
#include "rigdesign/occupancy/octomap_mapper.hpp"

#include <octomap/OcTree.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rigdesign/model/format_number.hpp"

namespace rigdesign::occupancy {
namespace {

// A probability as the log-odds OctoMap adds. 0 and 1 are +-infinity in OctoMap's own
// conversion; any step longer than the clamping span does what infinity does (the voxel goes
// straight to the clamp), so that step is used and nothing is ever infinite.
float log_odds_step(double probability, double clamp_span) {
  if (probability >= 1.0) return static_cast<float>(clamp_span + 1.0);
  if (probability <= 0.0) return static_cast<float>(-(clamp_span + 1.0));
  return static_cast<float>(std::log(probability / (1.0 - probability)));
}

double log_odds(double probability) {
  return std::log(probability / (1.0 - probability));
}

void check_octomap_params(const OctoMapParams& p) {
  const auto probability = [](double v) { return v >= 0.0 && v <= 1.0; };
  if (!(p.resolution >= 0.01 && p.resolution <= 1.0))
    throw std::invalid_argument("OctoMap: resolution must lie in [0.01, 1] m");
  if (!probability(p.hit) || !probability(p.miss))
    throw std::invalid_argument("OctoMap: hit and miss must be probabilities in [0, 1]");
  if (!(p.clamp_min > 0.0 && p.clamp_min < 0.5 && p.clamp_max > 0.5 && p.clamp_max < 1.0))
    throw std::invalid_argument("OctoMap: clamps must satisfy 0 < min < 0.5 < max < 1");
  if (!(p.z_max > p.min_height))
    throw std::invalid_argument("OctoMap: z_max must exceed min_height");
}

class OctoMapMapper final : public OccupancyMapper {
 public:
  explicit OctoMapMapper(const OctoMapParams& params) : params_(params), tree_(params.resolution) {
    tree_.setClampingThresMin(params.clamp_min);
    tree_.setClampingThresMax(params.clamp_max);
    tree_.setOccupancyThres(0.5);
    const double span = log_odds(params.clamp_max) - log_odds(params.clamp_min);
    hit_ = log_odds_step(params.hit, span);
    miss_ = log_odds_step(params.miss, span);
  }

  std::string name() const override { return octomap_label(params_); }

  VoxelLattice lattice() const override {
    return {params_.resolution, params_.resolution, 0.0, params_.z_max};
  }

  void update(double, std::span<const model::PointCloud> clouds, bool) override {
    for (const model::PointCloud& cloud : clouds) insert(cloud);
  }

  std::vector<costmap::VoxelKey> occupied() const override {
    const VoxelLattice grid = lattice();
    const double r = params_.resolution;
    std::vector<costmap::VoxelKey> keys;
    for (auto it = tree_.begin_leafs(), end = tree_.end_leafs(); it != end; ++it) {
      if (!tree_.isNodeOccupied(*it)) continue;
      // A pruned leaf stands for n^3 voxels of the finest level.
      const double size = it.getSize();
      const int n = std::max(1, static_cast<int>(std::lround(size / r)));
      const octomap::point3d c = it.getCoordinate();
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          for (int k = 0; k < n; ++k) {
            const model::Vec3 p(c.x() - size / 2 + (i + 0.5) * r, c.y() - size / 2 + (j + 0.5) * r,
                                c.z() - size / 2 + (k + 0.5) * r);
            const costmap::VoxelKey key = grid.key_at(p);
            if (key.z < 0 || key.z * r >= params_.z_max) continue;  // outside the band
            keys.push_back(key);
          }
        }
      }
    }
    costmap::sort_unique(keys);
    return keys;
  }

  std::size_t memory_bytes() const override { return tree_.memoryUsage(); }

 private:
  // octomap_server's insertScan (octomap_server/src/OctomapServer.cpp, 0.6.8): a marking
  // point's ray clears up to its end voxel, which is hit; a ground point's ray clears up to its
  // end voxel, which is left alone; each voxel then gets one update, a hit where any point ended.
  void insert(const model::PointCloud& cloud) {
    const octomap::point3d origin(cloud.origin.x(), cloud.origin.y(), cloud.origin.z());
    octomap::Pointcloud marking;
    octomap::KeySet free_cells, occupied_cells;
    for (const model::Point3f& p : cloud.points) {
      if (p.z() >= params_.min_height) marking.push_back(p.x(), p.y(), p.z());
    }
    tree_.computeUpdate(marking, origin, free_cells, occupied_cells, -1.0);
    for (const model::Point3f& p : cloud.points) {
      if (p.z() >= params_.min_height) continue;
      if (!tree_.computeRayKeys(origin, octomap::point3d(p.x(), p.y(), p.z()), ray_)) continue;
      free_cells.insert(ray_.begin(), ray_.end());  // the end voxel stays as it was
    }
    for (const octomap::OcTreeKey& key : free_cells) {
      if (occupied_cells.find(key) == occupied_cells.end()) tree_.updateNode(key, miss_);
    }
    for (const octomap::OcTreeKey& key : occupied_cells) tree_.updateNode(key, hit_);
  }

  OctoMapParams params_;
  octomap::OcTree tree_;
  octomap::KeyRay ray_;
  float hit_ = 0.0f;
  float miss_ = 0.0f;
};

}  // namespace

std::string octomap_label(const OctoMapParams& params) {
  return "OctoMap " + model::format_number(params.resolution, 3) + " m, hit " +
         model::format_number(params.hit, 3) + ", miss " + model::format_number(params.miss, 3);
}

std::unique_ptr<OccupancyMapper> make_octomap_mapper(const OctoMapParams& params) {
  check_octomap_params(params);
  return std::make_unique<OctoMapMapper>(params);
}

}  // namespace rigdesign::occupancy
