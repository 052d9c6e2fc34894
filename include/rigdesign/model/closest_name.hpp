#pragma once
/// "Did you mean": the known name a misspelt or habit-formed one was meant to be.
#include <string>
#include <vector>

namespace rigdesign::model {

/// The candidate `name` most likely means, or "" when none is close: a near miss by edit
/// distance (at most a third of the name's length), or the name with a unit suffix this
/// project's files require (`rpy` -> `rpy_deg`, the URDF habit; `horizontal` ->
/// `horizontal_deg`), or with a link suffix added or dropped (`velodyne_link` -> `velodyne`).
std::string closest_name(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace rigdesign::model
