#pragma once
/// Cost against coverage of the rigs a selection search evaluated (PNG or SVG by extension).
#include <string>
#include <vector>

#include "rigdesign/select/search.hpp"

namespace rigdesign::render {

/// Every explored rig as a dot (meeting the requirements or not), the Pareto front (no other
/// rig both cheaper and covering more), the budget as a vertical line and the chosen rig.
void plot_pareto(const std::vector<select::ExploredRig>& explored, double budget,
                 double chosen_cost, double chosen_coverage, const std::string& title,
                 const std::string& path, int width = 1100, int height = 650);

/// The explored rigs on the Pareto front, cheapest first.
std::vector<select::ExploredRig> pareto_front(const std::vector<select::ExploredRig>& explored);

}  // namespace rigdesign::render
