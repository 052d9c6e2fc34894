// Issue 35 items 2 and 5: the office_goals layout. The door leaves the gap asked for (read
// back from the leaf's own vertices, independently of the bisection that turned the gap into
// an angle), sized from the robot's width; the walkers give way to a robot near them.
#include <algorithm>
#include <catch2/catch.hpp>
#include <limits>

#include "rigdesign/scenarios/scenario_library.hpp"
#include "rigdesign/sim/office_goals_scene.hpp"

using namespace rigdesign;
using Catch::Matchers::WithinAbs;

namespace {

const model::SceneObject& object_named(const model::Scene& scene, const std::string& name) {
  const auto found = std::find_if(scene.objects.begin(), scene.objects.end(),
                                  [&](const model::SceneObject& o) { return o.name == name; });
  REQUIRE(found != scene.objects.end());
  return *found;
}

}  // namespace

TEST_CASE("office_goals: the door leaf leaves the gap asked for", "[scenario]") {
  for (const double gap : {0.45, 0.7, 0.89}) {
    const sim::OfficeGoalsLayout layout = sim::make_office_goals_scene(1, gap);
    const model::SceneObject& door = object_named(layout.scene, "door");
    // The frame's free side is its +y jamb at y = 3.5 m; the leaf hangs from the -y jamb.
    double leaf_top = -std::numeric_limits<double>::infinity();
    for (const model::Vec3& v : door.mesh.vertices) leaf_top = std::max(leaf_top, v.y());
    CHECK_THAT(3.5 - leaf_top, WithinAbs(gap, 1e-9));
    CHECK_THAT(layout.door_gap, WithinAbs(gap, 0.0));
  }
}

TEST_CASE("office_goals: the door gap is the robot's width plus 0.25 m, the goals on its line",
          "[scenario]") {
  CHECK_THAT(scenarios::office_door_gap(0.32), WithinAbs(0.89, 1e-12));
  CHECK_THAT(scenarios::office_door_gap(0.2), WithinAbs(0.65, 1e-12));
  // A robot wider than the door opened to 90 deg gets the full opening.
  CHECK_THAT(scenarios::office_door_gap(0.6), WithinAbs(sim::kOfficeDoorMaxGap, 0.0));
  const scenarios::ScenarioDefinition scenario =
      scenarios::make_costmap_scenario("office_goals", 3, 0.32);
  REQUIRE(scenario.route.size() == 7);
  // Goals 2 and 3 stand before and behind the door, halfway across its gap.
  CHECK_THAT(scenario.route[1].position.y(), WithinAbs(3.5 - 0.89 / 2, 1e-12));
  CHECK_THAT(scenario.route[2].position.y(), WithinAbs(3.5 - 0.89 / 2, 1e-12));
  CHECK(scenario.skip_unreachable);
  REQUIRE(scenario.drops.size() == 1);
  // The last goal lies past the stairwell: the straight way there crosses the drop.
  const model::Vec2 from = scenario.route[5].position;
  const model::Vec2 to = scenario.route[6].position;
  bool crosses = false;
  for (double s = 0; s <= 1.0; s += 0.01)
    crosses |= scenario.drops[0].contains(from + s * (to - from));
  CHECK(crosses);
  CHECK_FALSE(scenario.drops[0].contains(to));
}

TEST_CASE("office_goals: the seed moves the chairs and phases the walkers", "[scenario]") {
  const sim::OfficeGoalsLayout a = sim::make_office_goals_scene(1, 0.8);
  const sim::OfficeGoalsLayout b = sim::make_office_goals_scene(2, 0.8);
  const model::SceneObject& chair_a = object_named(a.scene, "chair_north_1_seat");
  const model::SceneObject& chair_b = object_named(b.scene, "chair_north_1_seat");
  CHECK((chair_a.mesh.vertices[0] - chair_b.mesh.vertices[0]).norm() > 1e-6);
  REQUIRE(a.scene.moving.size() == 2);
  for (const model::MovingObject& walker : a.scene.moving) CHECK(walker.gives_way_within > 0.0);
  // Walkers stay on their lines across the room, y 2.1 .. 3.9 m, over a whole cycle.
  for (double t = 0; t < 20; t += 0.25) {
    const model::Vec3 p = a.scene.moving[0].T_world_object(t).translation();
    CHECK(p.y() >= 2.1 - 1e-9);
    CHECK(p.y() <= 3.9 + 1e-9);
  }
}
