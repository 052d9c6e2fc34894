// Issue 35 item 3: the variants paper 2's Table 1 is run over, and its pooled average speed.
#include "rigdesign/scenarios/variant_sweep.hpp"

#include <catch2/catch.hpp>

using namespace rigdesign;
using Catch::Matchers::WithinAbs;

namespace {

model::Rig rig_of(const std::vector<std::string>& ids) {
  model::Rig rig;
  for (const std::string& id : ids) {
    model::Mount mount;
    mount.id = id;
    rig.mounts.push_back(mount);
  }
  return rig;
}

}  // namespace

TEST_CASE("rig variants: the whole rig, each N-1 subset, each mount alone", "[scenario]") {
  const std::vector<scenarios::RigVariant> pair =
      scenarios::rig_variants(rig_of({"camera", "lidar"}));
  REQUIRE(pair.size() == 3);  // with two mounts the N-1 subsets are the single mounts
  CHECK(pair[0].label == "camera + lidar");
  CHECK(pair[1].label == "camera only");
  CHECK(pair[2].label == "lidar only");
  const model::Rig three = rig_of({"camera", "lidar", "rear"});
  const std::vector<scenarios::RigVariant> triple = scenarios::rig_variants(three);
  REQUIRE(triple.size() == 7);  // 1 whole + 3 without one + 3 alone
  CHECK(triple[1].label == "lidar + rear");
  CHECK(triple[3].label == "camera + lidar");
  CHECK(triple[6].label == "rear only");
  const model::Rig subset = scenarios::rig_with(three, triple[2]);
  REQUIRE(subset.mounts.size() == 2);
  CHECK(subset.mounts[0].id == "camera");
  CHECK(subset.mounts[1].id == "rear");
  CHECK(scenarios::rig_variants(rig_of({"solo"})).size() == 1);
}

TEST_CASE("variant means: the average speed pooled over the legs to goals reached", "[scenario]") {
  scenarios::RunSummary a;  // 4 m in 10 s and 2 m in 10 s over its reached legs
  a.reached_distance = 6.0;
  a.reached_seconds = 20.0;
  a.goals_reached = 3;
  a.recovery_seconds = 12.0;
  a.drove_off = true;
  scenarios::RunSummary b;  // reached nothing: adds no distance and no time
  b.goals_reached = 0;
  b.goals_refused = 2;
  const scenarios::VariantMeans means = scenarios::means_of({a, b});
  CHECK_THAT(means.average_speed, WithinAbs(6.0 / 20.0, 1e-12));
  CHECK_THAT(means.goals_reached, WithinAbs(1.5, 1e-12));
  CHECK_THAT(means.goals_refused, WithinAbs(1.0, 1e-12));
  CHECK_THAT(means.recovery_seconds, WithinAbs(6.0, 1e-12));
  CHECK(means.drove_off == 1);
  CHECK(scenarios::means_of({}).average_speed == 0.0);
}
