#pragma once
/// SC margin against one pose axis of a chosen sensor (issue 15): how much room the rig has
/// to its sector thresholds as, say, the front camera's pitch sweeps its slot's range, with
/// the grid values the search chose from, the grid optimum and the refined pose; or (issue
/// 38) against a mount's pitch or yaw error with its tolerance marked. A margin below zero
/// misses a threshold. PNG or SVG by extension.
#include <string>
#include <utility>
#include <vector>

namespace rigdesign::render {

struct MarginCurve {
  std::string axis_label;        ///< "pitch [deg]"
  std::vector<double> at;        ///< axis values swept
  std::vector<double> smallest;  ///< the rig's smallest margin at each [points]
  /// Each sector's own margin at each [points], by sector name (the plot draws those the
  /// sweep changes).
  std::vector<std::pair<std::string, std::vector<double>>> sectors;
  std::vector<double> grid;  ///< the range's grid values, same unit as the samples
  double grid_choice = 0.0;  ///< the search's value
  double refined = 0.0;      ///< the refinement's value (== grid_choice if it kept the grid)
  /// Labelled values drawn instead of the grid optimum and refined lines (a tolerance sweep:
  /// -tolerance, nominal, +tolerance); empty: those two.
  std::vector<std::pair<double, std::string>> marks;
};

void plot_margin_curve(const MarginCurve& curve, const std::string& title, const std::string& path,
                       int width = 900, int height = 520);

}  // namespace rigdesign::render
