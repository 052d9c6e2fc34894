#pragma once
/// A 3D window of voxels that rolls with the robot in x and y over a fixed z band (DESIGN.md
/// section 7). Voxels sit on the same world-fixed lattice as the 2D window above them, so a
/// voxel column projects onto exactly one 2D cell. Storage is one byte per voxel, each
/// column's voxels contiguous (z fastest), which keeps column projection a linear scan.
#include <cstdint>
#include <vector>

#include "rigdesign/costmap/rolling_grid.hpp"

namespace rigdesign::costmap {

enum class VoxelState : std::uint8_t { unknown = 0, free = 1, occupied = 2 };

/// A voxel on the world lattice: x = floor(x / r), y = floor(y / r), z = floor((z - z_min) / r_z).
/// Ground-truth voxel sets for scoring use the same keys.
struct VoxelKey {
  int x = 0;
  int y = 0;
  int z = 0;
  friend auto operator<=>(const VoxelKey&, const VoxelKey&) = default;
};

/// Sorts `keys` and drops repeats: voxel sets are kept as sorted vectors.
void sort_unique(std::vector<VoxelKey>& keys);

class RollingVoxelGrid {
 public:
  RollingVoxelGrid() = default;
  /// Voxels over `window` in x and y and [z_min, z_max) in z, in layers of z_resolution [m]
  /// (the last layer may reach past z_max when the band is not a whole number of layers).
  /// Every voxel starts unknown. Preconditions (checked by check_costmap_params): a
  /// non-empty window, z_max > z_min, z_resolution > 0.
  RollingVoxelGrid(const GridWindow& window, double z_min, double z_max, double z_resolution);

  const GridWindow& window() const { return window_; }
  int layers() const { return layers_; }  ///< voxels per column
  double z_min() const { return z_min_; }
  double z_resolution() const { return z_resolution_; }

  std::size_t index(int x, int y, int z) const {
    return window_.index(x, y) * static_cast<std::size_t>(layers_) + static_cast<std::size_t>(z);
  }
  VoxelState state(int x, int y, int z) const {
    return static_cast<VoxelState>(voxels_[index(x, y, z)]);
  }
  void set(int x, int y, int z, VoxelState state) {
    voxels_[index(x, y, z)] = static_cast<std::uint8_t>(state);
  }
  /// Raw states (VoxelState values), column after column in the 2D window's row-major order.
  std::vector<std::uint8_t>& voxels() { return voxels_; }
  const std::vector<std::uint8_t>& voxels() const { return voxels_; }

  /// Moves the window (see RollingGrid::move_origin); entering columns become unknown.
  void move_origin(const Eigen::Vector2i& origin_cell);
  void recentre(const model::Vec2& centre_world) {
    move_origin(window_.origin_centred_on(centre_world));
  }
  void reset();

  /// The lattice key of window voxel (x, y, z).
  VoxelKey key_of(int x, int y, int z) const {
    return {window_.origin_cell.x() + x, window_.origin_cell.y() + y, z};
  }
  /// The lattice key of the voxel holding a world point (whether or not it is in the window).
  VoxelKey key_at(const model::Vec3& p_world) const;
  /// Every voxel in the given state, as lattice keys in ascending order.
  std::vector<VoxelKey> keys_in_state(VoxelState state) const;

 private:
  GridWindow window_;
  int layers_ = 0;
  double z_min_ = 0.0;
  double z_resolution_ = 0.05;
  std::vector<std::uint8_t> voxels_;
  std::vector<std::uint8_t> scratch_;
};

}  // namespace rigdesign::costmap
