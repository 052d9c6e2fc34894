#pragma once
/// Mean pooling of a depth camera's organised cloud, as paper 3 downsampled its RGB-D camera:
/// each block of k x k pixels becomes one point, the mean of the block's returns (NaN points
/// are no return). A block straddling a depth edge gives a point between the two surfaces, as
/// pooling a real depth image does.
#include "rigdesign/model/point_cloud.hpp"

namespace rigdesign::sim {

/// `organised` holds rows of `columns` pixels, row-major (a partial last row of blocks and a
/// partial last column are pooled over the pixels they have). The origin and orientation carry
/// over. Throws std::invalid_argument when columns or k is below 1 or the size is not a whole
/// number of rows.
model::PointCloud mean_pool(const model::PointCloud& organised, int columns, int k);

/// The columns of a row-major pixel grid of rays: how many lead with the first ray's image-plane
/// height
/// (sim::ray_pattern's rectangular grid of a pyramid camera); 0 for an empty pattern.
int pattern_columns(const std::vector<model::Vec3>& rays);

/// Whether `rays` form a full row-major pixel grid mean_pool can take (a pyramid camera's;
/// a cone's grid is clipped to its circle). Returns its columns, or 0 when it is not one.
int pixel_grid_columns(const std::vector<model::Vec3>& rays);

}  // namespace rigdesign::sim
