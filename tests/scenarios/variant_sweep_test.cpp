// Issue 35 item 3: the variants paper 2's Table 1 is run over, and its pooled average speed;
// issue 54: the sources of a subset nothing clears, and the bootstrap over seeds.
#include "rigdesign/scenarios/variant_sweep.hpp"

#include <catch2/catch.hpp>
#include <limits>

#include "rigdesign/scenarios/seed_bootstrap.hpp"

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

TEST_CASE("a subset none of whose sources clears has them clear; one that clears is kept",
          "[scenario]") {
  scenarios::ScenarioParams params;
  costmap::ObservationSource marks_only;
  marks_only.clearing = false;
  params.mount_sources = {{"scanner", marks_only}};       // paper 2's lidar: marking only
  const model::Rig both = rig_of({"camera", "scanner"});  // camera: the default source, clears
  bool added = true;
  const scenarios::ScenarioParams kept = scenarios::params_for_subset(both, params, added);
  CHECK_FALSE(added);
  REQUIRE(kept.mount_sources.size() == 1);
  CHECK_FALSE(kept.mount_sources[0].source.clearing);
  const scenarios::ScenarioParams alone =
      scenarios::params_for_subset(rig_of({"scanner"}), params, added);
  CHECK(added);
  REQUIRE(alone.mount_sources.size() == 1);
  CHECK(alone.mount_sources[0].source.clearing);
  CHECK(alone.mount_sources[0].source.marking);
}

TEST_CASE("percentile interval by nearest rank, worked by hand", "[scenario]") {
  // 1..40 shuffled; 95 %: ranks ceil(40 x 0.025) = 1 and ceil(40 x 0.975) = 39.
  std::vector<double> values;
  for (int i = 40; i >= 1; --i) values.push_back(i);
  const scenarios::Interval ninety_five = scenarios::percentile_interval(values, 0.95);
  CHECK(ninety_five.low == 1.0);
  CHECK(ninety_five.high == 39.0);
  // 50 %: ranks ceil(40 x 0.25) = 10 and ceil(40 x 0.75) = 30.
  const scenarios::Interval half = scenarios::percentile_interval(values, 0.5);
  CHECK(half.low == 10.0);
  CHECK(half.high == 30.0);
  CHECK_THROWS(scenarios::percentile_interval({}, 0.95));
  CHECK_THROWS(scenarios::percentile_interval({1.0}, 1.0));
}

TEST_CASE("seed resamples: indices in range, the same for the same seed", "[scenario]") {
  const auto a = scenarios::seed_resamples(20, 50, 7);
  const auto b = scenarios::seed_resamples(20, 50, 7);
  REQUIRE(a.size() == 50);
  CHECK(a == b);
  for (const auto& resample : a) {
    REQUIRE(resample.size() == 20);
    for (const std::size_t i : resample) CHECK(i < 20);
  }
  CHECK(scenarios::seed_resamples(20, 50, 8) != a);
}

TEST_CASE("resampled critical distance: the first margin none of the picked seeds collided at",
          "[scenario]") {
  // Four seeds at margins 0, 5 and 10 cm (true: collided). Seed 1 is clear at 5 cm and
  // collides at 10: a seed has no critical distance of its own.
  scenarios::VariantOutcome outcome;
  outcome.collided_by_margin = {{true, false, true, true},    // 0 cm
                                {false, false, true, true},   // 5 cm
                                {false, true, true, false}};  // 10 cm
  const std::vector<double> margins = {0.0, 0.05, 0.10, 0.15};
  CHECK(scenarios::resampled_critical_distance(outcome, margins, {1, 1}) == 0.0);
  CHECK(scenarios::resampled_critical_distance(outcome, margins, {0, 1}) == 0.05);
  CHECK(scenarios::resampled_critical_distance(outcome, margins, {0, 3, 3}) == 0.10);
  CHECK(scenarios::resampled_critical_distance(outcome, margins, {1, 2}) ==
        std::numeric_limits<double>::infinity());
  // Speeds pooled over the picked runs, a seed picked twice counted twice: seed 0 drove 2 m
  // in 10 s, seed 1 6 m in 10 s: picked {0, 0, 1}: 10 m in 30 s.
  outcome.runs.resize(2);
  outcome.runs[0].reached_distance = 2.0;
  outcome.runs[0].reached_seconds = 10.0;
  outcome.runs[1].reached_distance = 6.0;
  outcome.runs[1].reached_seconds = 10.0;
  CHECK_THAT(scenarios::resampled_average_speed(outcome, {0, 0, 1}), WithinAbs(10.0 / 30.0, 1e-12));
}
