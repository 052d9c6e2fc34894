#include "io/config/fov_readers.hpp"

#include <array>
#include <numbers>
#include <string_view>

#include "rigdesign/io/config/field_checks.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::io {
namespace {

using ShapePointer = std::shared_ptr<const model::FovShape>;

const std::string kFullAngle = "a full angle in degrees, in (0, 360]";
const std::string kElevation = "an elevation in degrees, in [-90, 90]";

std::string lens_angle(std::string_view shape) {
  return "a full angle in degrees, in (0, 180) for a " + std::string(shape);
}

ShapePointer read_pyramid(MapReader& fov) {
  const double horizontal =
      io::angle_in(fov, "horizontal_deg", 0, 180, false, lens_angle("pyramid"));
  const double vertical = io::angle_in(fov, "vertical_deg", 0, 180, false, lens_angle("pyramid"));
  return model::pyramid_fov(model::deg_to_rad(horizontal), model::deg_to_rad(vertical));
}

ShapePointer read_cone(MapReader& fov) {
  return model::cone_fov(
      model::deg_to_rad(io::angle_in(fov, "apex_deg", 0, 180, false, lens_angle("cone"))));
}

// A band without horizontal_deg spins a full turn.
ShapePointer read_band(MapReader& fov) {
  const double horizontal =
      fov.has("horizontal_deg")
          ? model::deg_to_rad(io::angle_in(fov, "horizontal_deg", 0, 360, true, kFullAngle))
          : 2 * std::numbers::pi;
  const double low = io::elevation(fov, "elevation_min_deg", kElevation);
  const double high = io::elevation(fov, "elevation_max_deg", kElevation);
  fov.require(high > low, "elevation_max_deg", "is not above elevation_min_deg",
              "elevation_min_deg < elevation_max_deg");
  return model::band_fov(horizontal, model::deg_to_rad(low), model::deg_to_rad(high));
}

ShapePointer read_planar(MapReader& fov) {
  const double horizontal = io::angle_in(fov, "horizontal_deg", 0, 360, true, kFullAngle);
  const double divergence =
      io::angle_in(fov, "beam_divergence_deg", 0, 180, false,
                   "the beam's full divergence angle in degrees, in (0, 180)");
  return model::planar_fov(model::deg_to_rad(horizontal), model::deg_to_rad(divergence));
}

struct FovReader {
  std::string_view shape;  // the `shape:` value, as model::FovShape::name() gives it
  ShapePointer (*read)(MapReader&);
};
constexpr std::array<FovReader, 4> kFovReaders = {{
    {"pyramid", read_pyramid},
    {"cone", read_cone},
    {"band", read_band},
    {"planar", read_planar},
}};

}  // namespace

model::FieldOfView read_fov(MapReader& fov) {
  std::vector<std::string> names;
  for (const FovReader& reader : kFovReaders) names.emplace_back(reader.shape);
  const auto index = fov.choice("shape", Need::required, names);
  if (!index) return {};
  model::FieldOfView result(kFovReaders[*index].read(fov));
  fov.text("note", Need::optional);
  fov.reject_unknown_keys();
  return result;
}

}  // namespace rigdesign::io
