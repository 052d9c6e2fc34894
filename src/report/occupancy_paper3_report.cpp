#include "rigdesign/report/occupancy_paper3_report.hpp"

#include <algorithm>
#include <cmath>

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/report/text_table.hpp"

namespace rigdesign::report {
namespace {

const occupancy::OccupancyRun* run_named(std::span<const occupancy::OccupancyRun> runs,
                                         const std::string& name) {
  for (const occupancy::OccupancyRun& run : runs)
    if (run.mapper == name) return &run;
  return nullptr;
}

void add_score_columns(TextTable& table, const char* prefix) {
  for (const char* h : {"P", "R", "F1", "F2", "F3"})
    table.add_column(std::string(prefix) + h, TextTable::Align::right);
}

std::vector<std::string> score_cells(const occupancy::Scores& s) {
  return {fixed_or_dash(s.precision, 3), fixed_or_dash(s.recall, 3), fixed_or_dash(s.f1, 3),
          fixed_or_dash(s.f2, 3), fixed_or_dash(s.f3, 3)};
}

void add_run_columns(TextTable& table) {
  for (const char* h :
       {"R late", "misses seen %", "trail m2", "ghost m2", "ms/upd", "Mpts/s", "memory MB"})
    table.add_column(h, TextTable::Align::right);
}

// The share of the person's missed voxels that held a point the mapper was given that frame.
double seen_share(const occupancy::OccupancyPhase& phase) {
  const std::size_t misses = phase.never_seen + phase.seen_not_kept;
  return misses == 0
             ? std::nan("")
             : 100.0 * static_cast<double>(phase.seen_not_kept) / static_cast<double>(misses);
}

std::vector<std::string> run_cells(const occupancy::OccupancyRun& run) {
  return {fixed_or_dash(run.all.object_late.recall, 3),
          fixed_or_dash(seen_share(run.all), 1),
          fixed_or_dash(run.all.trail_area, 2),
          fixed_or_dash(run.all.ghost_area, 2),
          fixed_or_dash(run.all.update_ms, 1),
          fixed_or_dash(run.all.points_per_second / 1e6, 2),
          fixed_or_dash(static_cast<double>(run.memory_bytes) / 1e6, 2)};
}

// The statements from the text, then those read off the tables, each with how many hold.
void print_statements(const std::vector<occupancy::Paper3Trend>& trends, std::ostream& out) {
  for (const bool from_text : {true, false}) {
    std::size_t listed = 0, hold = 0;
    out << (from_text
                ? "\nWhat paper 3's text states (paper: on its own table; here: on this run)\n"
                : "\nWhat paper 3's tables show: each table's best setting by P, R and F1\n");
    for (const occupancy::Paper3Trend& trend : trends) {
      if (trend.from_text != from_text) continue;
      ++listed;
      hold += trend.holds_here;
      out << "  [" << (trend.holds_in_paper ? "paper holds" : "paper FAILS") << ", "
          << (trend.holds_here ? "here holds" : "here fails") << "] " << trend.statement << " ("
          << trend.sweeps << ")\n    paper: " << trend.paper_detail
          << "\n    here:  " << trend.our_detail << '\n';
    }
    out << "  " << hold << " of " << listed << " hold here\n";
  }
}

}  // namespace

nlohmann::json scores_json(const occupancy::Scores& s) {
  const auto value = [](double v) { return std::isnan(v) ? nlohmann::json() : nlohmann::json(v); };
  return {{"precision", value(s.precision)},
          {"recall", value(s.recall)},
          {"f1", value(s.f1)},
          {"f2", value(s.f2)},
          {"f3", value(s.f3)}};
}

std::vector<occupancy::Paper3Sweep> paper3_sweeps_named(std::span<const std::string> names,
                                                        const occupancy::Paper3Common& common) {
  std::vector<occupancy::Paper3Sweep> sweeps;
  for (const std::string& name : occupancy::paper3_sweep_names()) {
    const bool wanted = std::any_of(names.begin(), names.end(), [&](const std::string& n) {
      return n == name || n == "paper3";
    });
    if (wanted) sweeps.push_back(occupancy::paper3_sweep(name, common));
  }
  return sweeps;
}

void print_paper3_report(std::span<const occupancy::Paper3Sweep> sweeps,
                         std::span<const occupancy::OccupancyRun> runs,
                         std::span<const std::string> extra, std::ostream& out) {
  const auto lookup = [&](const std::string& name) { return run_named(runs, name); };
  for (const occupancy::Paper3Sweep& sweep : sweeps) {
    TextTable table;
    table.add_column(sweep.swept, TextTable::Align::left);
    add_score_columns(table, "paper ");
    add_score_columns(table, "");
    add_run_columns(table);
    for (const occupancy::Paper3Setting& row : sweep.rows) {
      std::vector<std::string> cells = {row.label};
      for (std::string& cell : score_cells(row.paper)) cells.push_back(std::move(cell));
      const occupancy::OccupancyRun* run = lookup(occupancy::paper3_mapper_name(row));
      for (std::string& cell : score_cells(run->all.object)) cells.push_back(std::move(cell));
      for (std::string& cell : run_cells(*run)) cells.push_back(std::move(cell));
      table.add_row(std::move(cells));
    }
    out << "\n" << sweep.table << ", " << sweep.name << " (paper 3's numbers, then rigdesign's)\n";
    table.print(out, "  ");
  }
  if (!extra.empty()) {
    TextTable table;
    table.add_column("rigdesign's mappers on the same frames", TextTable::Align::left);
    add_score_columns(table, "");
    add_run_columns(table);
    for (const std::string& name : extra) {
      const occupancy::OccupancyRun* run = lookup(name);
      std::vector<std::string> cells = {name};
      for (std::string& cell : score_cells(run->all.object)) cells.push_back(std::move(cell));
      for (std::string& cell : run_cells(*run)) cells.push_back(std::move(cell));
      table.add_row(std::move(cells));
    }
    out << "\n";
    table.print(out, "  ");
  }
  out << "\nR late: recall with the map read one update late; misses seen %: the person's "
         "missed voxels that held a point the mapper was given that frame\n";
  print_statements(occupancy::paper3_trends(sweeps, lookup), out);
}

nlohmann::json paper3_report_json(std::span<const occupancy::Paper3Sweep> sweeps,
                                  std::span<const occupancy::OccupancyRun> runs) {
  const auto lookup = [&](const std::string& name) { return run_named(runs, name); };
  nlohmann::json report = {{"sweeps", nlohmann::json::array()},
                           {"trends", nlohmann::json::array()}};
  for (const occupancy::Paper3Sweep& sweep : sweeps) {
    nlohmann::json rows = nlohmann::json::array();
    for (const occupancy::Paper3Setting& row : sweep.rows) {
      const occupancy::OccupancyRun* run = lookup(occupancy::paper3_mapper_name(row));
      rows.push_back({{"setting", row.label},
                      {"mapper", run->mapper},
                      {"paper", scores_json(row.paper)},
                      {"rigdesign", scores_json(run->all.object)},
                      {"rigdesign_map_one_update_late", scores_json(run->all.object_late)},
                      {"misses_seen", run->all.seen_not_kept},
                      {"misses_never_seen", run->all.never_seen},
                      {"trail_area_m2", run->all.trail_area},
                      {"ghost_area_m2", run->all.ghost_area},
                      {"update_ms", run->all.update_ms},
                      {"points_per_second", run->all.points_per_second},
                      {"memory_bytes", run->memory_bytes}});
    }
    report["sweeps"].push_back(
        {{"name", sweep.name}, {"table", sweep.table}, {"swept", sweep.swept}, {"rows", rows}});
  }
  for (const occupancy::Paper3Trend& trend : occupancy::paper3_trends(sweeps, lookup)) {
    report["trends"].push_back({{"statement", trend.statement},
                                {"sweeps", trend.sweeps},
                                {"holds_in_paper", trend.holds_in_paper},
                                {"holds_here", trend.holds_here},
                                {"from_text", trend.from_text},
                                {"paper", trend.paper_detail},
                                {"rigdesign", trend.our_detail}});
  }
  return report;
}

}  // namespace rigdesign::report
