#include "rigdesign/model/fov_shape.hpp"

#include <algorithm>

namespace rigdesign::model {
namespace {

// Samples per angle of the steepest-ray search: 64 intervals put samples on the edges, the
// centre and every 1/64 of the span (a cone's full turn then hits the four axis directions).
constexpr int kDownSamples = 65;

}  // namespace

double FovShape::steepest_down(const Mat3& R_robot_sensor) const {
  const AngularDomain range = domain();
  double best = -1.0;
  for (int i = 0; i < kDownSamples; ++i) {
    const double u = range.u_min + (range.u_max - range.u_min) * i / (kDownSamples - 1);
    for (int j = 0; j < kDownSamples; ++j) {
      const double v = range.v_min + (range.v_max - range.v_min) * j / (kDownSamples - 1);
      best = std::max(best, -(R_robot_sensor * direction(u, v)).z());
    }
  }
  return best;
}

FieldOfView::FieldOfView() : shape_(pyramid_fov(0.0, 0.0)) {}

FieldOfView::FieldOfView(std::shared_ptr<const FovShape> shape) : shape_(std::move(shape)) {}

}  // namespace rigdesign::model
