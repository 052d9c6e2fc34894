#include "rigdesign/render/pareto_plot.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

#include "cairo_canvas.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::render {
namespace {

using render::Anchor;
using render::draw_text;
using render::set_colour;

constexpr Rgb kFeasible{0.0, 0.55, 0.25};
constexpr Rgb kChosen{0.85, 0.1, 0.1};

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
  render::draw_to_file(path, width, height, [&](cairo_t* cairo) {
    const double left = 90, top = 60, right = width - 40.0, bottom = height - 80.0;
    double max_cost = std::max(budget, chosen_cost);
    for (const select::ExploredRig& rig : explored) max_cost = std::max(max_cost, rig.cost);
    max_cost = max_cost > 0 ? max_cost * 1.05 : 1.0;
    const auto x = [&](double cost) { return left + (right - left) * cost / max_cost; };
    const auto y = [&](double share) { return bottom - (bottom - top) * share; };

    set_colour(cairo, kInkColour);
    // A long relaxation step in the title is set smaller rather than cut at the edges (about
    // 0.6 em per character in bold DejaVu Sans).
    const double title_size =
        std::min(19.0, (width - 40.0) /
                           (0.62 * static_cast<double>(std::max<std::size_t>(title.size(), 1))));
    draw_text(cairo, title, width / 2.0, 34, title_size, Anchor::centre, true);
    cairo_set_line_width(cairo, 1);
    const double magnitude = std::pow(10.0, std::floor(std::log10(max_cost / 5)));
    const double step = magnitude * (max_cost / magnitude > 25   ? 5
                                     : max_cost / magnitude > 10 ? 2
                                                                 : 1);
    for (double cost = 0; cost <= max_cost; cost += step) {
      set_colour(cairo, kGridColour);
      cairo_move_to(cairo, x(cost), top);
      cairo_line_to(cairo, x(cost), bottom);
      cairo_stroke(cairo);
      set_colour(cairo, kInkColour);
      draw_text(cairo, model::format_number(cost, 6), x(cost), bottom + 20, 13, Anchor::centre);
    }
    for (int percent = 0; percent <= 100; percent += 20) {
      set_colour(cairo, kGridColour);
      cairo_move_to(cairo, left, y(percent / 100.0));
      cairo_line_to(cairo, right, y(percent / 100.0));
      cairo_stroke(cairo);
      set_colour(cairo, kInkColour);
      draw_text(cairo, std::to_string(percent), left - 8, y(percent / 100.0) + 5, 13,
                Anchor::right);
    }
    draw_text(cairo, "rig cost C = C_s + C_t + C_c [USD]", (left + right) / 2, height - 30.0, 14,
              Anchor::centre);
    cairo_save(cairo);
    cairo_translate(cairo, 28, (top + bottom) / 2);
    cairo_rotate(cairo, -std::numbers::pi / 2);
    draw_text(cairo, "mean SC complete over 360 deg [%]", 0, 0, 14, Anchor::centre);
    cairo_restore(cairo);

    set_colour(cairo, kFeasible, 0.8);
    for (const select::ExploredRig& rig : explored) {
      if (!rig.feasible) continue;
      cairo_new_sub_path(cairo);
      cairo_arc(cairo, x(rig.cost), y(rig.mean_complete), 3.5, 0, 2 * std::numbers::pi);
    }
    cairo_fill(cairo);
    const std::vector<select::ExploredRig> front = pareto_front(explored);
    set_colour(cairo, kInkColour);
    cairo_set_line_width(cairo, 1.8);
    for (std::size_t i = 0; i < front.size(); ++i) {
      if (i > 0) cairo_line_to(cairo, x(front[i].cost), y(front[i - 1].mean_complete));
      i == 0 ? cairo_move_to(cairo, x(front[i].cost), y(front[i].mean_complete))
             : cairo_line_to(cairo, x(front[i].cost), y(front[i].mean_complete));
    }
    cairo_stroke(cairo);
    const double dash[] = {8.0, 5.0};
    cairo_set_dash(cairo, dash, 2, 0);
    set_colour(cairo, kChosen);
    cairo_move_to(cairo, x(budget), top);
    cairo_line_to(cairo, x(budget), bottom);
    cairo_stroke(cairo);
    cairo_set_dash(cairo, nullptr, 0, 0);
    draw_text(cairo, "budget " + model::format_number(budget, 6) + " USD", x(budget) + 6, top + 16,
              13);
    if (chosen_cost > 0) {
      cairo_new_sub_path(cairo);
      cairo_arc(cairo, x(chosen_cost), y(chosen_coverage), 8, 0, 2 * std::numbers::pi);
      cairo_set_line_width(cairo, 2.5);
      cairo_stroke(cairo);
      // Over the budget (the policy ran out) the rig is the cheapest valid one, not a choice.
      draw_text(
          cairo,
          chosen_cost <= budget ? "chosen (cheapest valid rig)" : "cheapest valid rig: OVER BUDGET",
          x(chosen_cost) + 11, y(chosen_coverage) - 8, 13, Anchor::left, true);
    }
    // Legend.
    double ly = bottom - 50;
    set_colour(cairo, kFeasible);
    cairo_new_sub_path(cairo);
    cairo_arc(cairo, right - 210, ly - 5, 4, 0, 2 * std::numbers::pi);
    cairo_fill(cairo);
    set_colour(cairo, kInkColour);
    draw_text(cairo, "a rig meeting the requirements", right - 198, ly, 13);
    ly += 20;
    cairo_set_line_width(cairo, 1.8);
    cairo_move_to(cairo, right - 218, ly - 5);
    cairo_line_to(cairo, right - 202, ly - 5);
    cairo_stroke(cairo);
    draw_text(cairo, "Pareto front", right - 198, ly, 13);
  });
}

}  // namespace rigdesign::render
