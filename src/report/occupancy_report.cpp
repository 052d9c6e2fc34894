#include "rigdesign/report/occupancy_report.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/statistics.hpp"
#include "rigdesign/report/occupancy_paper3_report.hpp"
#include "rigdesign/report/text_table.hpp"

namespace rigdesign::report {
namespace {

std::string truth_label(occupancy::TruthKind truth) {
  switch (truth) {
    case occupancy::TruthKind::link_volumes:
      return "the fused clouds' points inside volumes round the person's links, voxelised "
             "(paper 3, III-B, eqs. 1-4)";
    case occupancy::TruthKind::sensor_points:
      return "the points whose ray ends on the person, voxelised (--truth-from points)";
    case occupancy::TruthKind::mesh_surface:
      return "the person's whole mesh surface, unseen back included (--truth-from surface)";
  }
  return "";
}

std::string region_label(occupancy::ScoringRegion region, double object_margin) {
  return region == occupancy::ScoringRegion::hull
             ? std::string("inside the convex hull of the person's truth points (paper 3, III-C)")
             : "within " + model::format_number(object_margin) +
                   " m of the truth's box (--fp-region margin)";
}

nlohmann::json phase_json(const occupancy::OccupancyPhase& phase) {
  const auto value = [](double v) { return std::isnan(v) ? nlohmann::json() : nlohmann::json(v); };
  return {{"frames", phase.frames},
          {"person", scores_json(phase.object)},
          {"master", scores_json(phase.master)},
          {"ghost_area_m2", value(phase.ghost_area)},
          {"ghost_area_max_m2", phase.ghost_area_max},
          {"trail_area_m2", value(phase.trail_area)},
          {"trail_length_m", value(phase.trail_length)},
          {"trail_length_max_m", phase.trail_length_max},
          {"master_ghost_area_m2", value(phase.master_ghost_area)},
          {"misses_never_seen", phase.never_seen},
          {"misses_seen_not_kept", phase.seen_not_kept},
          {"mark_delay_median_s", value(model::median(phase.mark_delays))},
          {"mark_delay_p95_s", value(model::percentile(phase.mark_delays, 0.95))},
          {"clear_delay_median_s", value(model::median(phase.clear_delays))},
          {"clear_delay_p95_s", value(model::percentile(phase.clear_delays, 0.95))},
          {"marks", phase.mark_delays.size()},
          {"clears", phase.clear_delays.size()},
          {"update_ms", value(phase.update_ms)},
          {"points_per_second", value(phase.points_per_second)}};
}

void print_tables(const std::vector<occupancy::OccupancyRun>& runs,
                  const std::vector<occupancy::VoxelMapperParams>& grid, std::ostream& out) {
  TextTable scores;
  scores.add_column("voxel m", TextTable::Align::right);
  scores.add_column("persistence", TextTable::Align::left);
  for (const char* h :
       {"P", "R", "F1", "F2", "F3", "P mov", "R mov", "F2 mov", "P still", "R still", "F2 still"}) {
    scores.add_column(h, TextTable::Align::right);
  }
  TextTable cell;
  cell.add_column("voxel m", TextTable::Align::right);
  cell.add_column("persistence", TextTable::Align::left);
  for (const char* h : {"ghost mov m2", "ghost still m2", "trail mov m", "trail still m", "mark s",
                        "clear mov s", "clear still s", "pending", "never seen", "seen lost",
                        "grid F2", "grid ghost m2", "ms/upd", "Mpts/s"}) {
    cell.add_column(h, TextTable::Align::right);
  }
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const occupancy::OccupancyRun& r = runs[i];
    const std::string voxel = fixed(grid[i].voxel, 2),
                      label = occupancy::persistence_label(grid[i]);
    scores.add_row(
        {voxel, label, fixed_or_dash(r.all.object.precision, 3),
         fixed_or_dash(r.all.object.recall, 3), fixed_or_dash(r.all.object.f1, 3),
         fixed_or_dash(r.all.object.f2, 3), fixed_or_dash(r.all.object.f3, 3),
         fixed_or_dash(r.moving.object.precision, 3), fixed_or_dash(r.moving.object.recall, 3),
         fixed_or_dash(r.moving.object.f2, 3), fixed_or_dash(r.stationary.object.precision, 3),
         fixed_or_dash(r.stationary.object.recall, 3), fixed_or_dash(r.stationary.object.f2, 3)});
    const std::size_t misses = r.all.never_seen + r.all.seen_not_kept;
    const auto share = [&](std::size_t n) {
      return misses == 0
                 ? std::string("-")
                 : fixed(100.0 * static_cast<double>(n) / static_cast<double>(misses), 0) + "%";
    };
    cell.add_row(
        {voxel, label, fixed_or_dash(r.moving.ghost_area, 2),
         fixed_or_dash(r.stationary.ghost_area, 2), fixed_or_dash(r.moving.trail_length_max, 2),
         fixed_or_dash(r.stationary.trail_length_max, 2),
         fixed_or_dash(model::median(r.all.mark_delays), 1),
         fixed_or_dash(model::median(r.moving.clear_delays), 1),
         fixed_or_dash(model::median(r.stationary.clear_delays), 1),
         std::to_string(r.pending_changes), share(r.all.never_seen), share(r.all.seen_not_kept),
         fixed_or_dash(r.all.master.f2, 3), fixed_or_dash(r.all.master_ghost_area, 2),
         fixed_or_dash(r.all.update_ms, 1), fixed_or_dash(r.all.points_per_second / 1e6, 2)});
  }
  out << "Near the person (paper 3's score), mean over frames; mov = robot moving, still = "
         "standing\n";
  scores.print(out, "  ");
  out << "\nWhole cell: ghost area and trail (mean / max), median delays, misses by cause, planner "
         "grid\n";
  cell.print(out, "  ");
}

}  // namespace

std::string occupancy_run_label(const OccupancyReport& report, std::size_t run) {
  if (run >= report.grid.size()) return report.runs[run].mapper;
  return model::format_number(report.grid[run].voxel, 3) + " m, " +
         occupancy::persistence_label(report.grid[run]);
}

std::string occupancy_frames_csv(const std::vector<occupancy::OccupancyRun>& runs) {
  std::ostringstream csv;
  csv << "mapper,time_s,robot_moving,points,update_ms,tp,fp,fn,precision,recall,f1,f2,f3,never_"
         "seen,"
         "seen_not_kept,ghost_area_m2,trail_area_m2,trail_length_p90_m,trail_length_oldest_m,"
         "master_precision,master_recall,master_f2,"
         "master_ghost_area_m2\n";
  for (const occupancy::OccupancyRun& run : runs) {
    for (const occupancy::OccupancyFrame& f : run.frames) {
      const occupancy::Scores s = occupancy::scores_of(f.object);
      const occupancy::Scores m = occupancy::scores_of(f.master);
      csv << '"' << run.mapper << "\"," << model::format_number(f.time, 6) << ',' << f.robot_moving
          << ',' << f.points << ',' << model::format_number(f.update_seconds * 1e3, 4) << ','
          << f.object.true_positives << ',' << f.object.false_positives << ','
          << f.object.false_negatives << ',' << model::format_number(s.precision, 4) << ','
          << model::format_number(s.recall, 4) << ',' << model::format_number(s.f1, 4) << ','
          << model::format_number(s.f2, 4) << ',' << model::format_number(s.f3, 4) << ','
          << f.misses.never_seen << ',' << f.misses.seen_not_kept << ','
          << model::format_number(f.ghost_area, 4) << ',' << model::format_number(f.trail_area, 4)
          << ',' << model::format_number(f.trail_length, 4) << ','
          << model::format_number(f.trail_length_oldest, 4) << ','
          << model::format_number(m.precision, 4) << ',' << model::format_number(m.recall, 4) << ','
          << model::format_number(m.f2, 4) << ',' << model::format_number(f.master_ghost_area, 4)
          << '\n';
    }
  }
  return csv.str();
}

nlohmann::json occupancy_json(const OccupancyReport& report) {
  nlohmann::json document = {
      {"rig", report.rig_name},
      {"scene", report.scene},
      {"rate_hz", report.rate},
      {"duration_s", report.duration},
      {"moving_until_s", report.moving_until},
      {"camera_stride", report.camera_stride},
      {"camera_pooling", report.camera_pooling},
      {"truth", truth_label(report.truth)},
      {"false_positive_region", region_label(report.region, report.object_margin)},
      {"runs", nlohmann::json::array()}};
  for (std::size_t i = 0; i < report.runs.size(); ++i) {
    const occupancy::OccupancyRun& run = report.runs[i];
    const bool ours = i < report.grid.size();
    document["runs"].push_back(
        {{"mapper", run.mapper},
         {"voxel_m", run.resolution},
         {"persistence", ours ? occupancy::persistence_label(report.grid[i]) : "-"},
         {"memory_bytes", run.memory_bytes},
         {"all", phase_json(run.all)},
         {"moving", phase_json(run.moving)},
         {"stationary", phase_json(run.stationary)},
         {"pending_changes", run.pending_changes},
         {"missed_marks", run.missed_marks},
         {"missed_clears", run.missed_clears}});
  }
  if (!report.sweeps.empty()) document["paper3"] = paper3_report_json(report.sweeps, report.runs);
  return document;
}

void print_occupancy(const OccupancyReport& report, std::ostream& out) {
  out << report.rig_name << " in the " << report.scene << " scene: " << report.sensors
      << " sensors, " << report.runs.front().frames.size() << " frames at "
      << model::format_number(report.rate, 4) << " Hz, robot moving until "
      << model::format_number(report.moving_until, 4) << " s\n"
      << "truth: " << truth_label(report.truth) << "\n"
      << "false positives counted " << region_label(report.region, report.object_margin) << "\n\n";
  if (report.sweeps.empty()) {
    print_tables(report.runs, report.grid, out);
  } else {
    out << "paper 3's sweeps: every setting once, " << report.runs.size()
        << " mappers on the same frames\n";
    print_paper3_report(report.sweeps, report.runs, report.extra, out);
  }
  out << "\nPareto-optimal (F2 up, ghost area down, ms per update down):";
  for (const std::string& label : report.pareto) out << "\n  " << label;
  out << '\n';
  if (!report.folder.empty()) {
    out << "wrote occupancy_frames.csv, occupancy_summary.json and occupancy_pareto.png to "
        << report.folder << '\n';
  }
}

}  // namespace rigdesign::report
