// Issue 33: the range fit lists first the hypothesis with the most posterior probability
// within the decision radius (the acceptable error) of it. Checked on the parts: the mass a
// posterior grid holds within a radius, counted by hand, and the order on a scenario.
#include <catch2/catch.hpp>
#include <cmath>

#include "rigdesign/localize/emitter_localizer.hpp"
#include "rigdesign/localize/log_generator.hpp"
#include "rigdesign/localize/position_posterior.hpp"

using namespace rigdesign;

TEST_CASE("posterior mass within a radius: uniform 10 x 10 grid of 1 m cells", "[localize]") {
  // Every cell the same density: each holds 1/100 of the probability. Around the centre
  // (5, 5) the cell centres (i + 0.5, j + 0.5) within 1.6 m are the 12 with offsets
  // (+-0.5, +-0.5), (+-1.5, +-0.5) and (+-0.5, +-1.5) (distances 0.71 and 1.58 m; the next,
  // (+-1.5, +-1.5), lie 2.12 m away).
  const localize::PositionPosterior uniform = localize::make_posterior(
      model::Vec2::Zero(), 1.0, 10, 10, std::vector<double>(100, 0.0), 0.95);
  CHECK(uniform.mass_within(model::Vec2(5, 5), 1.6) == Approx(12.0 / 100));
  CHECK(uniform.mass_within(model::Vec2(5, 5), 0.5) == Approx(0.0));
  CHECK(uniform.mass_within(model::Vec2(5, 5), 100.0) == Approx(1.0));
  // A corner: only the cells inside the grid count (offsets (0.5, 0.5), (1.5, 0.5), (0.5, 1.5)).
  CHECK(uniform.mass_within(model::Vec2(0, 0), 1.6) == Approx(3.0 / 100));
  // Cells never evaluated (-infinity) hold nothing.
  std::vector<double> half(100, 0.0);
  for (int i = 0; i < 50; ++i) half[static_cast<std::size_t>(i)] = -INFINITY;
  const localize::PositionPosterior upper =
      localize::make_posterior(model::Vec2::Zero(), 1.0, 10, 10, half, 0.95);
  CHECK(upper.mass_within(model::Vec2(5, 5), 1.6) == Approx(6.0 / 50));
}

TEST_CASE("range fit: hypotheses are listed by their probability within the decision radius",
          "[localize]") {
  for (const char* name : {"loop", "hallway", "room"}) {
    INFO(name);
    localize::ScenarioParams params;
    params.seed = 4;
    const localize::Scenario scenario = localize::make_scenario(name, params);
    const localize::EmitterEstimate estimate =
        localize::localize_emitter(scenario.log, 0, localize::LocalizeMethod::nls, {});
    REQUIRE_FALSE(estimate.hypotheses.empty());
    for (std::size_t i = 0; i < estimate.hypotheses.size(); ++i) {
      REQUIRE(estimate.hypotheses[i].probability_nearby);
      const double nearby = *estimate.hypotheses[i].probability_nearby;
      CHECK(nearby >= 0.0);
      CHECK(nearby <= 1.0 + 1e-12);
      if (i > 0) CHECK(nearby <= *estimate.hypotheses[i - 1].probability_nearby);
    }
  }
}
