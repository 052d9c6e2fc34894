#include "description_bounds.hpp"

#include "rigdesign/model/coordinate_limit.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {
namespace {

std::string written(const model::Vec3& v) {
  return model::format_number(v.x()) + " " + model::format_number(v.y()) + " " +
         model::format_number(v.z());
}

}  // namespace

void require_positive_size(const model::Vec3& size, const model::SourceLocation& where,
                           const std::string& field, const std::string& expected) {
  if (size.allFinite() && (size.array() > 0.0).all()) return;
  throw model::InputError(model::Diagnostic{where, field, "is '" + written(size) + "'", expected});
}

void require_position_in_bounds(const model::Vec3& position, const model::SourceLocation& where,
                                const std::string& field) {
  if (position.allFinite() && position.cwiseAbs().maxCoeff() <= model::kMaxCoordinate) return;
  throw model::InputError(
      model::Diagnostic{where, field, "places it at '" + written(position) + "' m, beyond +-1e8 m",
                        "positions within +-1e8 m of the robot (a value in the wrong unit?)"});
}

}  // namespace rigdesign::io
