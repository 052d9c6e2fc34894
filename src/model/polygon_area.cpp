#include "rigdesign/model/polygon_area.hpp"

namespace rigdesign::model {

double signed_area(const std::vector<Vec2>& polygon) {
  double twice_area = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[(i + 1) % polygon.size()];
    twice_area += a.x() * b.y() - b.x() * a.y();
  }
  return twice_area / 2;
}

}  // namespace rigdesign::model
