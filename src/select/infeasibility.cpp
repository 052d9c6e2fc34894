#include "select/infeasibility.hpp"

#include <algorithm>
#include <limits>
#include <optional>

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"
#include "select/hardware_limits.hpp"
#include "select/search_rules.hpp"

namespace rigdesign::select {
namespace {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

// The metric no option of the catalog meets on its own, and the best any gives.
std::optional<std::string> unmet_metric(const std::vector<std::vector<CatalogOption>>& options,
                                        const SatisficingTargets& targets) {
  double fastest = 0.0;
  double finest = kUnbounded;
  double least_noise = kUnbounded;
  bool any = false;
  std::vector<bool> immune(targets.lighting.size(), false);
  for (const auto& slot : options) {
    for (const CatalogOption& option : slot) {
      any = true;
      const metrics::MountMetrics& m = option.metrics;
      fastest = std::max(fastest, m.frequency);
      finest = std::min(finest, m.point_spacing);
      least_noise = std::min(least_noise, m.noise);
      for (std::size_t i = 0; i < targets.lighting.size(); ++i)
        immune[i] = immune[i] || m.light.immune_to(targets.lighting[i]);
    }
  }
  if (!any) return "the catalog offers no slot option";
  if (fastest < targets.min_frequency)
    return "F: no sensor mode of the catalog runs at " +
           model::format_number(targets.min_frequency, 4) +
           " Hz or faster (the fastest: " + model::format_number(fastest, 4) + " Hz)";
  if (targets.max_spacing && finest > *targets.max_spacing)
    return "R: no sensor mode of the catalog resolves " +
           model::format_number(*targets.max_spacing * 1000, 4) +
           " mm at its distance (the finest: " + model::format_number(finest * 1000, 4) + " mm)";
  if (targets.max_noise && least_noise > *targets.max_noise)
    return "N: no sensor mode of the catalog is within " +
           model::format_number(*targets.max_noise * 1000, 4) +
           " mm noise (the least: " + model::format_number(least_noise * 1000, 4) + " mm)";
  for (std::size_t i = 0; i < targets.lighting.size(); ++i) {
    if (!immune[i])
      return "L: no sensor mode of the catalog works in " + to_string(targets.lighting[i]);
  }
  return std::nullopt;
}

// A sector angle where every option the search kept, together, misses the threshold.
std::optional<std::string> uncoverable_sector(const SearchProblem& problem,
                                              const SatisficingTargets& targets,
                                              const SelectionSpace& space) {
  for (std::size_t i = 0; i < problem.sectors.size(); ++i) {
    const SearchSector& sector = problem.sectors[i];
    for (const int a : sector.angles) {
      geometry::SectionRaster all(problem.grids[a]);
      for (const auto& slot : problem.slots)
        for (const SearchOption& option : slot) all |= option.section(a);
      if (meets(all.complete_share(), sector.min_complete) &&
          meets(all.floor_share(), sector.min_floor))
        continue;
      return "R2: the sector '" + targets.sectors[i].name + "' cannot be met: every option " +
             "meeting F, R, N and L together covers " +
             model::format_number(100 * all.complete_share(), 3) + " % (floor " +
             model::format_number(100 * all.floor_share(), 3) + " %) at " +
             model::format_number(model::rad_to_deg(space.angle(static_cast<std::size_t>(a))), 4) +
             " deg, below " + model::format_number(100 * sector.min_complete, 3) + " % (" +
             model::format_number(100 * sector.min_floor, 3) + " %)";
    }
  }
  return std::nullopt;
}

}  // namespace

std::string infeasibility_cause(const SearchProblem& problem,
                                const std::vector<std::vector<CatalogOption>>& options,
                                const SatisficingTargets& targets, const SelectionSpace& space) {
  if (auto metric = unmet_metric(options, targets)) return *metric;
  if (auto sector = uncoverable_sector(problem, targets, space)) return *sector;
  const SearchProblem unlimited = with_unlimited_hardware(problem);
  const bool robust = problem.robustness.any();
  const std::string which =
      robust ? "meeting the requirements and surviving the failures" : "meeting the requirements";
  const SearchResult cheapest = branch_and_bound(unlimited);
  if (!cheapest.found) {
    if (!robust) return "no combination of the catalog's options meets every sector together";
    SearchProblem plain = unlimited;
    plain.robustness = {};
    return branch_and_bound(plain).found
               ? "robustness: rigs meet the sectors, but none survives every failure asked "
                 "(--robust or the requirements' robustness) with the after-failure thresholds"
               : "no combination of the catalog's options meets every sector together";
  }
  // With only one limit back (its largest item, free), the search says whether any rig
  // fits under it: the capacity pruning makes that quick.
  const RigLoad needed = load_of(problem, cheapest);
  std::vector<std::string> causes;
  std::string cpu_id;
  const double cores = largest_capacity(problem.cpus, cpu_id);
  SearchProblem cpu_only = unlimited;
  cpu_only.cpus = {{cpu_id, cores, 0.0, {}, {}}};
  if (!branch_and_bound(cpu_only).found) {
    causes.push_back("CPU: no rig " + which + " loads less than the " +
                     model::format_number(cores, 4) +
                     " core-equivalents of the catalog's largest "
                     "CPU, " +
                     cpu_id + " (the cheapest rig with an unlimited, free CPU loads " +
                     model::format_number(needed.cpu, 4) + ")");
  }
  std::string link_id;
  const double bits = transfer_bottleneck(problem.transfer, link_id);
  SearchProblem transfer_only = unlimited;
  transfer_only.transfer = {{link_id, bits, 0.0, {}, {}}};
  transfer_only.slots = problem.slots;  // each sensor's own components priced as they are
  if (!branch_and_bound(transfer_only).found) {
    const std::string sent = " (the cheapest rig with unlimited, free transfer sends " +
                             model::format_number(needed.bandwidth * 8 / 1e9, 4) + " Gbit/s)";
    causes.push_back(
        link_id.empty()
            ? "transfer: every rig " + which +
                  " has a sensor whose bandwidth no per-sensor transfer component of the "
                  "catalog carries" +
                  sent
            : "transfer: no rig " + which + " sends less than the " +
                  model::format_number(bits / 1e9, 4) +
                  " Gbit/s of the catalog's largest transfer item, " + link_id + sent);
  }
  if (causes.empty()) {
    return "CPU and transfer together: rigs " + which +
           " fit the largest CPU and rigs fit the "
           "largest transfer item, but none fits both";
  }
  return model::join(causes, "; ");
}

}  // namespace rigdesign::select
