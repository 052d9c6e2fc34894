#pragma once
/// Cost against coverage of the rigs a selection search found meeting its requirements (PNG
/// or SVG by extension).
#include <string>
#include <vector>

#include "rigdesign/select/search.hpp"

namespace rigdesign::render {

/// Every rig meeting the requirements as a dot, the Pareto front through them (no other such
/// rig both cheaper and covering more), the budget as a vertical line and the chosen rig.
/// Rigs missing a requirement are left out: the front is a trade-off among valid designs.
void plot_pareto(const std::vector<select::ExploredRig>& explored, double budget,
                 double chosen_cost, double chosen_coverage, const std::string& title,
                 const std::string& path, int width = 1100, int height = 650);

/// The feasible explored rigs on the Pareto front, cheapest first.
std::vector<select::ExploredRig> pareto_front(const std::vector<select::ExploredRig>& explored);

}  // namespace rigdesign::render
