#include "rigdesign/select/relaxation.hpp"

#include <catch2/catch.hpp>

#include "rigdesign/model/input_error.hpp"
#include "rigdesign/select/relax_step.hpp"

using namespace rigdesign;

namespace {

model::Requirements base() {
  model::Requirements requirements;
  requirements.file = "req.yaml";
  requirements.distance = 3.5;
  requirements.robot_speed = model::MotionBetweenFrames{1.0, 0.07, {}};
  requirements.smallest_obstacle = 0.15;
  requirements.lighting = {model::LightCondition::dark, model::LightCondition::indoor};
  model::SectorRequirement back;
  back.name = "back";
  back.min_floor_coverage = 0.5;
  requirements.sectors = {back};
  return requirements;
}

model::RelaxationStep step(const std::string& requirement, double to) {
  model::RelaxationStep relaxation;
  relaxation.requirement = requirement;
  relaxation.to = to;
  relaxation.where = {"policy.yaml", 7, 5};
  return relaxation;
}

}  // namespace

TEST_CASE("relaxing requirements changes the derived satisficing metrics") {
  model::Requirements relaxed = select::relax(base(), step("robot_speed.max_speed", 0.7));
  CHECK(relaxed.required_frequency() == Approx(10.0));  // 0.7 / 0.07
  relaxed = select::relax(relaxed, step("smallest_obstacle.size", 0.2));
  CHECK(*relaxed.smallest_obstacle == 0.2);
  relaxed = select::relax(relaxed, step("sectors.back.min_floor_coverage", 0.3));
  CHECK(relaxed.sectors[0].min_floor_coverage == 0.3);
  model::RelaxationStep drop;
  drop.requirement = "lighting";
  drop.drop = model::LightCondition::dark;
  relaxed = select::relax(relaxed, drop);
  CHECK(relaxed.lighting == std::vector<model::LightCondition>{model::LightCondition::indoor});
}

TEST_CASE("a step that tightens, names an unknown requirement or leaves the range is bad input") {
  const auto message = [](const model::RelaxationStep& s) {
    try {
      select::relax(base(), s);
    } catch (const model::InputError& error) {
      return error.diagnostics().front().message();
    }
    return std::string("no error");
  };
  CHECK(message(step("robot_speed.max_speed", 1.2)).find("tightens") != std::string::npos);
  CHECK(message(step("smallest_obstacle.size", 0.1)).find("tightens") != std::string::npos);
  CHECK(message(step("robot_speed.top_speed", 0.5)).find("is not a relaxable requirement") !=
        std::string::npos);
  CHECK(message(step("sectors.front.min_floor_coverage", 0.3)).find("is not stated") !=
        std::string::npos);
  CHECK(message(step("sectors.back.min_floor_coverage", -0.1)).find("cannot be") !=
        std::string::npos);
  CHECK(message(step("robot_speed.max_speed", 0.5)) == "no error");
  CHECK(message(step("robot_speed.max_speed", 1.2)).rfind("policy.yaml:7:5: steps.relax:", 0) == 0);
}

TEST_CASE("check_policy applies every step in order") {
  model::RelaxationPolicy policy;
  policy.steps = {step("robot_speed.max_speed", 0.8), step("robot_speed.max_speed", 0.6)};
  CHECK(select::check_policy(base(), policy).robot_speed->speed == 0.6);
  policy.steps = {step("robot_speed.max_speed", 0.6), step("robot_speed.max_speed", 0.8)};
  CHECK_THROWS_AS(select::check_policy(base(), policy),
                  model::InputError);  // the second step tightens
}
