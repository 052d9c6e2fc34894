#include "rigdesign/render/pareto_plot.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

#include "cairo_canvas.hpp"
#include "chart_axes.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::render {
namespace {

constexpr Rgb kFeasible{0.0, 0.55, 0.25};
constexpr Rgb kChosen{0.85, 0.1, 0.1};

// Cost from zero on x, the mean complete coverage share on y.
struct ParetoChart {
  PlotArea area;
  double max_cost = 1.0;  // [USD] the x axis's end
  double x(double cost) const { return area.left + (area.right - area.left) * cost / max_cost; }
  double y(double share) const { return area.bottom - (area.bottom - area.top) * share; }
};

ParetoChart pareto_chart(const std::vector<select::ExploredRig>& explored, double budget,
                         double chosen_cost, int width, int height) {
  double max_cost = std::max(budget, chosen_cost);
  for (const select::ExploredRig& rig : explored) max_cost = std::max(max_cost, rig.cost);
  return {{90, 60, width - 40.0, height - 80.0}, max_cost > 0 ? max_cost * 1.05 : 1.0};
}

// A long relaxation step in the title is set smaller rather than cut at the edges (about
// 0.6 em per character in bold DejaVu Sans).
void draw_pareto_title(cairo_t* cairo, const std::string& title, int width) {
  const double size = std::min(
      19.0, (width - 40.0) / (0.62 * static_cast<double>(std::max<std::size_t>(title.size(), 1))));
  set_colour(cairo, kInkColour);
  draw_text(cairo, title, width / 2.0, 34, size, Anchor::centre, true);
}

void draw_pareto_axes(cairo_t* cairo, const ParetoChart& chart) {
  const Axis x{tick_values(0, chart.max_cost, tick_step(chart.max_cost, 5, StepRounding::down)),
               [&](double cost) { return chart.x(cost); }};
  const Axis y{tick_values(0, 100, 20), [&](double percent) { return chart.y(percent / 100.0); }};
  draw_ticks(cairo, chart.area, x, y);
  draw_x_title(cairo, chart.area, "rig cost C = C_s + C_t + C_c [USD]", 50);
  draw_y_title(cairo, chart.area, "mean SC complete over 360 deg [%]", 28);
}

// Every rig meeting the requirements as a dot, and the front as a staircase through them:
// between two front rigs the cheaper one's coverage holds until the dearer one's cost.
void draw_explored_rigs(cairo_t* cairo, const ParetoChart& chart,
                        const std::vector<select::ExploredRig>& explored) {
  set_colour(cairo, kFeasible, 0.8);
  for (const select::ExploredRig& rig : explored) {
    if (!rig.feasible) continue;
    cairo_new_sub_path(cairo);
    cairo_arc(cairo, chart.x(rig.cost), chart.y(rig.mean_complete), 3.5, 0, 2 * std::numbers::pi);
  }
  cairo_fill(cairo);
  const std::vector<select::ExploredRig> front = pareto_front(explored);
  set_colour(cairo, kInkColour);
  cairo_set_line_width(cairo, 1.8);
  for (std::size_t i = 0; i < front.size(); ++i) {
    if (i > 0) cairo_line_to(cairo, chart.x(front[i].cost), chart.y(front[i - 1].mean_complete));
    i == 0 ? cairo_move_to(cairo, chart.x(front[i].cost), chart.y(front[i].mean_complete))
           : cairo_line_to(cairo, chart.x(front[i].cost), chart.y(front[i].mean_complete));
  }
  cairo_stroke(cairo);
}

void draw_budget_and_choice(cairo_t* cairo, const ParetoChart& chart, double budget,
                            double chosen_cost, double chosen_coverage) {
  const PlotArea& area = chart.area;
  const double dash[] = {8.0, 5.0};
  cairo_set_dash(cairo, dash, 2, 0);
  set_colour(cairo, kChosen);
  cairo_move_to(cairo, chart.x(budget), area.top);
  cairo_line_to(cairo, chart.x(budget), area.bottom);
  cairo_stroke(cairo);
  cairo_set_dash(cairo, nullptr, 0, 0);
  draw_text(cairo, "budget " + model::format_number(budget, 6) + " USD", chart.x(budget) + 6,
            area.top + 16, 13);
  if (chosen_cost <= 0) return;
  cairo_new_sub_path(cairo);
  cairo_arc(cairo, chart.x(chosen_cost), chart.y(chosen_coverage), 8, 0, 2 * std::numbers::pi);
  cairo_set_line_width(cairo, 2.5);
  cairo_stroke(cairo);
  // Over the budget (the policy ran out) the rig is the cheapest valid one, not a choice.
  draw_text(
      cairo,
      chosen_cost <= budget ? "chosen (cheapest valid rig)" : "cheapest valid rig: OVER BUDGET",
      chart.x(chosen_cost) + 11, chart.y(chosen_coverage) - 8, 13, Anchor::left, true);
}

void draw_pareto_legend(cairo_t* cairo, const PlotArea& area) {
  double ly = area.bottom - 50;
  set_colour(cairo, kFeasible);
  cairo_new_sub_path(cairo);
  cairo_arc(cairo, area.right - 210, ly - 5, 4, 0, 2 * std::numbers::pi);
  cairo_fill(cairo);
  set_colour(cairo, kInkColour);
  draw_text(cairo, "a rig meeting the requirements", area.right - 198, ly, 13);
  ly += 20;
  cairo_set_line_width(cairo, 1.8);
  cairo_move_to(cairo, area.right - 218, ly - 5);
  cairo_line_to(cairo, area.right - 202, ly - 5);
  cairo_stroke(cairo);
  draw_text(cairo, "Pareto front", area.right - 198, ly, 13);
}

}  // namespace

std::vector<select::ExploredRig> pareto_front(const std::vector<select::ExploredRig>& explored) {
  std::vector<select::ExploredRig> sorted;
  std::copy_if(explored.begin(), explored.end(), std::back_inserter(sorted),
               [](const select::ExploredRig& rig) { return rig.feasible; });
  std::sort(sorted.begin(), sorted.end(),
            [](const select::ExploredRig& a, const select::ExploredRig& b) {
              return a.cost < b.cost || (a.cost == b.cost && a.mean_complete > b.mean_complete);
            });
  std::vector<select::ExploredRig> front;
  for (const select::ExploredRig& rig : sorted) {
    if (front.empty() || rig.mean_complete > front.back().mean_complete) front.push_back(rig);
  }
  return front;
}

void plot_pareto(const std::vector<select::ExploredRig>& explored, double budget,
                 double chosen_cost, double chosen_coverage, const std::string& title,
                 const std::string& path, int width, int height) {
  const ParetoChart chart = pareto_chart(explored, budget, chosen_cost, width, height);
  draw_to_file(path, width, height, [&](cairo_t* cairo) {
    draw_pareto_title(cairo, title, width);
    draw_pareto_axes(cairo, chart);
    draw_explored_rigs(cairo, chart, explored);
    draw_budget_and_choice(cairo, chart, budget, chosen_cost, chosen_coverage);
    draw_pareto_legend(cairo, chart.area);
  });
}

}  // namespace rigdesign::render
