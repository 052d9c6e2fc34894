#pragma once
// Reads x, y, z out of a packed binary body. Both formats give each coordinate a column of
// values at a fixed stride: rows of records (PCD binary, PLY binary) have the record size
// as stride; PCD binary_compressed stores all values of one field, then the next, so there
// the stride is the value's own size. Private to io.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rigdesign/model/coordinate_limit.hpp"
#include "rigdesign/model/point_cloud.hpp"

namespace rigdesign::io {

enum class CoordinateType { float32, float64 };

/// One coordinate's values in a buffer: value i starts at byte first + i * stride.
struct CoordinateColumn {
  std::size_t first = 0;
  std::size_t stride = 0;
  CoordinateType type = CoordinateType::float32;
};

using model::kMaxCoordinate;

/// Finite points and how many were dropped for a NaN or infinite coordinate.
struct CollectedPoints {
  std::vector<model::Point3f> points;
  std::size_t dropped_non_finite = 0;
  /// The first finite point beyond model::kMaxCoordinate, by its index in the file.
  std::optional<std::size_t> first_far_index;
  model::Point3f first_far;

  /// Keeps `point` when all three coordinates are finite, counts it as dropped otherwise.
  void keep_if_finite(const model::Point3f& point);

  /// Throws InputError naming `path` and the first point beyond kMaxCoordinate, if any.
  void require_in_range(const std::string& path) const;

  /// The cloud of the kept points with the file's sensor pose.
  model::PointCloud into_cloud(const model::Point3f& origin,
                               const Eigen::Quaternionf& orientation) &&;
};

/// A double as the nearest float; beyond float's range, an infinity of its sign (which
/// keep_if_finite then drops) rather than the undefined conversion.
float narrow_to_float(double value);

/// Appends the points made of value i of each column, i < count, to `collected`, keeping
/// the finite ones. Returns false, having read nothing, when `bytes` is too short to hold
/// `count` values in some column; the caller reports the truncation.
/// Assumes the file's byte order is the machine's (little-endian, checked at compile time).
bool collect_points(std::string_view bytes, std::size_t count,
                    const std::array<CoordinateColumn, 3>& columns, CollectedPoints& collected);

}  // namespace rigdesign::io
