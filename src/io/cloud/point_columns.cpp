#include "io/cloud/point_columns.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {
namespace {

// PCD and PLY binary_little_endian bodies are little-endian; they are copied as they are.
static_assert(std::endian::native == std::endian::little,
              "cloud_io reads binary bodies without byte swapping");

std::size_t value_size(CoordinateType type) {
  return type == CoordinateType::float32 ? sizeof(float) : sizeof(double);
}

// Whether count values of `column` lie inside a buffer of `size` bytes, without overflowing
// on counts a corrupt header makes huge.
bool column_fits(const CoordinateColumn& column, std::size_t count, std::size_t size) {
  if (count == 0) return true;
  const std::size_t width = value_size(column.type);
  if (column.first > size || size - column.first < width) return false;
  const std::size_t room_after_first = size - column.first - width;
  return column.stride == 0 || count - 1 <= room_after_first / column.stride;
}

float read_coordinate(const char* at, CoordinateType type) {
  if (type == CoordinateType::float32) {
    float value;
    std::memcpy(&value, at, sizeof value);
    return value;
  }
  double value;
  std::memcpy(&value, at, sizeof value);
  return narrow_to_float(value);
}

}  // namespace

void CollectedPoints::keep_if_finite(const model::Point3f& point) {
  if (point.allFinite()) {
    if (!first_far_index && point.cwiseAbs().maxCoeff() > kMaxCoordinate) {
      first_far_index = points.size() + dropped_non_finite;
      first_far = point;
    }
    points.push_back(point);
  } else {
    ++dropped_non_finite;
  }
}

void CollectedPoints::require_in_range(const std::string& path) const {
  if (!first_far_index) return;
  const auto coordinate = [](float value) { return model::format_number(value, 6); };
  throw model::InputError(model::Diagnostic{
      {path, 0, 0},
      "point " + std::to_string(*first_far_index),
      "lies at (" + coordinate(first_far.x()) + ", " + coordinate(first_far.y()) + ", " +
          coordinate(first_far.z()) + ") m, beyond +-" + model::format_number(kMaxCoordinate) +
          " m on some axis",
      "coordinates within +-1e8 m (shift a geo-referenced cloud to a local origin first)"});
}

float narrow_to_float(double value) {
  constexpr double kLargestFloat = std::numeric_limits<float>::max();
  if (std::isfinite(value) && std::abs(value) > kLargestFloat) {
    constexpr float kInfinity = std::numeric_limits<float>::infinity();
    return value > 0 ? kInfinity : -kInfinity;
  }
  return static_cast<float>(value);
}

bool collect_points(std::string_view bytes, std::size_t count,
                    const std::array<CoordinateColumn, 3>& columns, CollectedPoints& collected) {
  for (const CoordinateColumn& column : columns) {
    if (!column_fits(column, count, bytes.size())) return false;
  }
  collected.points.reserve(collected.points.size() + count);
  const auto coordinate = [&](std::size_t axis, std::size_t i) {
    const CoordinateColumn& column = columns[axis];
    return read_coordinate(bytes.data() + column.first + i * column.stride, column.type);
  };
  for (std::size_t i = 0; i < count; ++i) {
    collected.keep_if_finite({coordinate(0, i), coordinate(1, i), coordinate(2, i)});
  }
  return true;
}

model::PointCloud CollectedPoints::into_cloud(const model::Point3f& origin,
                                              const Eigen::Quaternionf& orientation) && {
  model::PointCloud cloud;
  cloud.points = std::move(points);
  cloud.origin = origin;
  cloud.orientation = orientation;
  return cloud;
}

}  // namespace rigdesign::io
