#include "rigdesign/metrics/calibration_overlap.hpp"

#include <algorithm>
#include <numeric>

#include "rigdesign/model/format_number.hpp"

namespace rigdesign::metrics {
namespace {

std::string square_metres(double area) {
  return model::format_number(area, 3) + " m^2";
}

}  // namespace

std::vector<std::vector<std::size_t>> overlap_components(const Covisibility& overlap,
                                                         double min_overlap) {
  const std::size_t n = overlap.mount_ids.size();
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const PairOverlap& pair : overlap.pairs) {
    if (pair.column_area >= min_overlap) parent[root(pair.b)] = root(pair.a);
  }
  std::vector<std::vector<std::size_t>> components;
  std::vector<int> slot(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t r = root(i);
    if (slot[r] < 0) {
      slot[r] = static_cast<int>(components.size());
      components.emplace_back();
    }
    components[static_cast<std::size_t>(slot[r])].push_back(i);
  }
  std::stable_sort(components.begin(), components.end(),
                   [](const auto& x, const auto& y) { return x.size() > y.size(); });
  return components;
}

RequirementResult calibration_verdict(const model::Rig& rig,
                                      const model::CalibrationRequirement& required,
                                      const Covisibility& overlap) {
  RequirementResult result;
  result.id = "R9";
  result.title = "calibration overlap";
  result.field = "calibration";
  result.where = required.where;
  result.unit = "m^2";
  result.bound = Bound::at_least;
  result.required = required.min_overlap;
  std::vector<std::string> edges;
  std::vector<std::string> missing;
  double weakest = overlap.pairs.empty() ? 0.0 : overlap.pairs.front().column_area;
  for (const PairOverlap& pair : overlap.pairs) {
    const std::string name = overlap.mount_ids[pair.a] + "-" + overlap.mount_ids[pair.b];
    (pair.column_area >= required.min_overlap ? edges : missing)
        .push_back(name + " " + square_metres(pair.column_area));
    weakest = std::min(weakest, pair.column_area);
  }
  const std::vector<std::vector<std::size_t>> components =
      overlap_components(overlap, required.min_overlap);
  std::string found = "pairs sharing >= " + square_metres(required.min_overlap) + " within " +
                      model::format_number(overlap.distance, 3) +
                      " m: " + (edges.empty() ? std::string("none") : model::join(edges));
  if (required.all_pairs) {
    result.metric = "smallest pair overlap";
    result.actual = weakest;
    result.verdict = missing.empty() ? Verdict::pass : Verdict::fail;
    result.explanation = "every pair must share >= " + square_metres(required.min_overlap) + "; " +
                         (missing.empty() ? found : "too little: " + model::join(missing));
  } else {
    result.metric = "sensors cut off";
    result.unit = "";
    result.bound = Bound::at_most;
    result.required = 0.0;
    std::size_t cut_off = 0;
    for (std::size_t c = 1; c < components.size(); ++c) cut_off += components[c].size();
    result.actual = static_cast<double>(cut_off);
    result.verdict = components.size() <= 1 ? Verdict::pass : Verdict::fail;
    if (components.size() <= 1) {
      result.explanation = "every sensor reaches every other through " + found;
    } else {
      std::vector<std::string> groups;
      for (std::size_t c = 1; c < components.size(); ++c) {
        std::vector<std::string> names;
        for (const std::size_t m : components[c]) names.push_back(overlap.mount_ids[m]);
        groups.push_back(model::join(names, " + "));
      }
      result.explanation = "cut off from the rest: " + model::join(groups, "; ") + "; " + found;
    }
  }
  // Point at the mounts a reviewer must move: those cut off (or, for `all`, the weakest pair).
  std::vector<std::size_t> named;
  for (std::size_t c = 1; c < components.size(); ++c)
    named.insert(named.end(), components[c].begin(), components[c].end());
  if (named.empty() && result.verdict == Verdict::fail) {
    for (const PairOverlap& pair : overlap.pairs) {
      if (pair.column_area == weakest) {
        named = {pair.a, pair.b};
        break;
      }
    }
  }
  for (const std::size_t m : named) {
    result.limiting_mounts.push_back(overlap.mount_ids[m]);
    if (result.rig_where.file.empty()) {
      result.rig_where = rig.mounts[m].where;
    } else {
      result.also_where.push_back(rig.mounts[m].where);
    }
  }
  return result;
}

}  // namespace rigdesign::metrics
