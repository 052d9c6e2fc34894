#include "rigdesign/model/closest_name.hpp"

#include <algorithm>

namespace rigdesign::model {
namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// Files say degrees only in fields ending _deg (the brief's unit rule): a name without the
// suffix is the commonest slip of someone used to URDF's radians.
bool is_unit_suffixed(const std::string& name, const std::string& candidate) {
  return candidate == name + "_deg";
}

// URDF link names differ in a `_link` or `_frame` suffix from driver to description
// (`velodyne_link` for the Jackal's `velodyne`): too far apart for the edit distance.
bool differs_by_link_suffix(const std::string& name, const std::string& candidate) {
  for (const char* suffix : {"_link", "_frame"}) {
    if (name == candidate + suffix || candidate == name + suffix) return true;
  }
  return false;
}

}  // namespace

std::string closest_name(const std::string& name, const std::vector<std::string>& candidates) {
  for (const std::string& candidate : candidates) {
    if (is_unit_suffixed(name, candidate) || differs_by_link_suffix(name, candidate))
      return candidate;
  }
  std::string closest;
  std::size_t best = name.size() / 3 + 1;  // suggest only near misses
  for (const std::string& candidate : candidates) {
    const std::size_t distance = edit_distance(name, candidate);
    if (distance < best) {
      best = distance;
      closest = candidate;
    }
  }
  return closest;
}

}  // namespace rigdesign::model
