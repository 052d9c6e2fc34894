#include "rigdesign/select/relaxation.hpp"

#include <algorithm>

#include "rigdesign/select/relax_step.hpp"

namespace rigdesign::select {
namespace {

// Each requirement the final requirements state, and the requirements without it.
std::vector<std::pair<std::string, model::Requirements>> without_each(
    const model::Requirements& requirements) {
  std::vector<std::pair<std::string, model::Requirements>> variants;
  const auto add = [&](const std::string& name, auto change) {
    model::Requirements copy = requirements;
    change(copy);
    variants.emplace_back(name, std::move(copy));
  };
  if (requirements.min_frequency)
    add("R3 range.min_frequency", [](model::Requirements& r) { r.min_frequency.reset(); });
  if (requirements.object_dynamics)
    add("R4 object_dynamics", [](model::Requirements& r) { r.object_dynamics.reset(); });
  if (requirements.robot_speed)
    add("R5 robot_speed", [](model::Requirements& r) { r.robot_speed.reset(); });
  if (requirements.smallest_obstacle)
    add("R6 smallest_obstacle", [](model::Requirements& r) { r.smallest_obstacle.reset(); });
  if (requirements.max_noise)
    add("R7 accuracy", [](model::Requirements& r) { r.max_noise.reset(); });
  for (const model::LightCondition condition : requirements.lighting) {
    add("R8 lighting " + to_string(condition), [condition](model::Requirements& r) {
      r.lighting.erase(std::find(r.lighting.begin(), r.lighting.end(), condition));
    });
  }
  for (const model::SectorRequirement& sector : requirements.sectors) {
    add("R2 sectors." + sector.name, [name = sector.name](model::Requirements& r) {
      r.sectors.erase(
          std::find_if(r.sectors.begin(), r.sectors.end(),
                       [&](const model::SectorRequirement& s) { return s.name == name; }));
    });
  }
  return variants;
}

std::vector<BindingRequirement> binding_requirements(const SelectionSpace& space,
                                                     const model::Requirements& requirements,
                                                     const Selection& last, double budget,
                                                     const ProgressSink& progress) {
  std::vector<BindingRequirement> all;
  const auto variants = without_each(requirements);
  const double total = static_cast<double>(variants.size());
  for (const auto& [name, relaxed] : variants) {
    const double done = static_cast<double>(all.size());
    // Each probe is a whole select: its phases count as a share of the probe.
    const auto probe = [&, name = name](const PhaseProgress& at) {
      if (progress)
        progress({"binding requirements", done + (at.total > 0 ? at.done / at.total : 0.0), total,
                  "probes", "without " + name + ": " + at.phase});
    };
    const Selection selection = select_cheapest(space, relaxed, probe, /*probe=*/true);
    all.push_back({name, selection.found, selection.found ? selection.cost.total : 0.0});
  }
  std::vector<BindingRequirement> binding;
  for (const BindingRequirement& item : all) {
    if (item.feasible_without && (item.cost_without <= budget || !last.found))
      binding.push_back(item);
  }
  if (!binding.empty()) return binding;
  // None alone suffices: those whose removal saves the most.
  std::vector<BindingRequirement> cheaper;
  for (const BindingRequirement& item : all) {
    if (item.feasible_without && last.found && item.cost_without < last.cost.total)
      cheaper.push_back(item);
  }
  std::sort(cheaper.begin(), cheaper.end(),
            [](const auto& a, const auto& b) { return a.cost_without < b.cost_without; });
  return cheaper;
}

}  // namespace

model::Requirements check_policy(const model::Requirements& requirements,
                                 const model::RelaxationPolicy& policy) {
  model::Requirements current = requirements;
  for (const model::RelaxationStep& step : policy.steps) current = relax(current, step);
  return current;
}

RelaxationOutcome select_within_budget(
    const SelectionSpace& space, const model::Requirements& requirements,
    const model::RelaxationPolicy& policy, double budget,
    const std::function<void(const RelaxationIteration&)>& on_iteration,
    const ProgressSink& progress) {
  RelaxationOutcome outcome;
  model::Requirements current = requirements;
  for (std::size_t i = 0; i <= policy.steps.size(); ++i) {
    RelaxationIteration iteration;
    if (i > 0) {
      iteration.relaxed = describe(current, policy.steps[i - 1]);
      current = relax(current, policy.steps[i - 1]);
    }
    iteration.requirements = current;
    iteration.targets = satisficing_targets(current);
    iteration.selection = select_cheapest(space, current, progress);
    iteration.within_budget = iteration.selection.found && iteration.selection.cost.total <= budget;
    if (on_iteration) on_iteration(iteration);
    outcome.iterations.push_back(std::move(iteration));
    if (outcome.iterations.back().within_budget) {
      outcome.within_budget = true;
      return outcome;
    }
  }
  PhaseClock clock(outcome.phases, &progress);
  clock.start("binding requirements");
  outcome.binding =
      binding_requirements(space, current, outcome.iterations.back().selection, budget, progress);
  clock.stop(std::to_string(without_each(current).size()) +
             " searches, each without one requirement");
  return outcome;
}

}  // namespace rigdesign::select
