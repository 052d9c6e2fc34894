// Closed sets as one table each: every value has one name, names parse back to their value,
// and the names are the ones the file formats document (rigs/README.md, DESIGN.md section 3).
#include <catch2/catch.hpp>

#include "rigdesign/costmap/costmap.hpp"
#include "rigdesign/localize/emitter_localizer.hpp"
#include "rigdesign/model/sensor.hpp"

using namespace rigdesign;

namespace {

template <typename Enum, std::size_t N>
void check_round_trip(const model::NameTable<Enum, N>& table,
                      const std::vector<std::string>& documented) {
  CHECK(model::names_of(table) == documented);
  for (const auto& [value, name] : table) {
    CHECK(model::value_in(table, name) == value);
    CHECK(model::name_in(table, value) == name);
  }
  CHECK_FALSE(model::value_in(table, "no such name").has_value());
}

}  // namespace

TEST_CASE("each enum's names are one table that parses back", "[model]") {
  check_round_trip(model::kTechnologyNames,
                   {"tof", "structured_light", "active_stereo", "passive_stereo",
                    "lidar_3d_spinning", "lidar_2d", "solid_state_lidar"});
  check_round_trip(model::kLightConditionNames, {"dark", "indoor", "sunlight"});
  check_round_trip(model::kBasisNames, {"datasheet", "measured", "estimate"});
  check_round_trip(costmap::kObstacleLayerNames, {"obstacle", "voxel"});
  check_round_trip(localize::kLocalizeMethodNames, {"wls", "nls", "map"});
  CHECK(localize::parse_localize_method("map") == localize::LocalizeMethod::map);
}

TEST_CASE("a table out of enum order is caught", "[model]") {
  constexpr model::NameTable<model::Basis, 3> swapped = {{{model::Basis::measured, "measured"},
                                                          {model::Basis::datasheet, "datasheet"},
                                                          {model::Basis::estimate, "estimate"}}};
  STATIC_REQUIRE_FALSE(model::covers_in_order(swapped));
  STATIC_REQUIRE(model::covers_in_order(model::kBasisNames));
}
