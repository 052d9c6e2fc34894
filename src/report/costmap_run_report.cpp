#include "rigdesign/report/costmap_run_report.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "rigdesign/report/text_table.hpp"

namespace rigdesign::report {
namespace {

double milliseconds(double seconds) {
  return seconds * 1e3;
}

// Each simulated mount's rate and latency, as the run used them.
nlohmann::json sensors_json(const std::vector<std::string>& mount_ids,
                            const scenarios::ScenarioResult& result) {
  nlohmann::json sensors = nlohmann::json::array();
  for (std::size_t i = 0; i < result.timings.size() && i < mount_ids.size(); ++i) {
    const scenarios::MountTiming& t = result.timings[i];
    sensors.push_back({{"mount", mount_ids[i]},
                       {"rate_hz", 1.0 / t.period},
                       {"phase_s", t.phase},
                       {"driver_s", t.driver},
                       {"filtering_s", t.filtering},
                       {"latency_s", t.latency()}});
  }
  return sensors;
}

nlohmann::json stops_json(const scenarios::ScenarioResult& result) {
  nlohmann::json stops = nlohmann::json::array();
  for (const scenarios::StopOutcome& stop : result.stops) {
    stops.push_back(
        {{"name", stop.name},
         {"reached", stop.reached},
         {"reached_time_s", stop.reached ? nlohmann::json(stop.reached_time) : nlohmann::json()},
         {"refused", stop.refused},
         {"reason", stop.reason},
         {"leg_distance_m", stop.leg_distance},
         {"leg_s", stop.leg_seconds}});
  }
  return stops;
}

}  // namespace

std::string outcome_text(const scenarios::ScenarioResult& result) {
  if (result.collided) {
    return "collision with " + result.collision_object +
           " at t = " + fixed(result.collision_time, 2) + " s (robot at x " +
           fixed(result.collision_position.x(), 2) + ", y " +
           fixed(result.collision_position.y(), 2) + " m)";
  }
  if (result.drove_off) {
    return "none; drove off the " + result.drop_name +
           " at t = " + fixed(result.drove_off_time, 2) + " s at " +
           fixed(result.drove_off_speed, 2) + " m/s";
  }
  if (result.gave_up) return "none; gave up at t = " + fixed(result.end_time, 2) + " s";
  return result.reached_goal ? "none; goal reached at t = " + fixed(result.end_time, 2) + " s"
                             : "none; goal not reached by t = " + fixed(result.end_time, 2) + " s";
}

nlohmann::json costmap_run_json(const CostmapContext& context, const CostmapRun& run) {
  const scenarios::ScenarioParams& params = run.params;
  const scenarios::ScenarioResult& result = run.result;
  const scenarios::TimeSummary update = scenarios::summarize_times(result.update_seconds);
  const scenarios::TimeSummary plan = scenarios::summarize_times(result.planner_seconds);
  nlohmann::json trajectory = nlohmann::json::array();
  for (const scenarios::TrajectorySample& sample : result.trajectory) {
    trajectory.push_back(
        {sample.time, sample.pose.position.x(), sample.pose.position.y(), sample.pose.yaw});
  }
  nlohmann::json summary = {
      {"rig", context.rig_name},
      {"scenario", context.scenario},
      {"seed", context.seed},
      {"layer", run.layer},
      {"hit_layer", run.hit_layer},
      {"observation_persistence", run.persistence},
      {"hit", params.costmap.hit.hit},
      {"hit_max", params.costmap.hit.hit_max},
      {"resolution_m", params.costmap.resolution},
      {"window_m", params.costmap.size_x},
      {"update_rate_hz", params.update_rate},
      {"speed_m_per_s", params.follower.speed},
      {"collided", result.collided},
      {"collision_time_s",
       result.collided ? nlohmann::json(result.collision_time) : nlohmann::json()},
      {"collision_object", result.collision_object},
      {"min_clearance_m", std::isfinite(result.min_clearance) ? nlohmann::json(result.min_clearance)
                                                              : nlohmann::json()},
      {"min_clearance_time_s", result.min_clearance_time},
      {"min_clearance_object", result.min_clearance_object},
      {"reached_goal", result.reached_goal},
      {"end_time_s", result.end_time},
      {"updates", result.updates},
      {"planner_failures", result.planner_failures},
      {"update_ms", {{"median", milliseconds(update.median)}, {"p99", milliseconds(update.p99)}}},
      {"planner_ms", {{"median", milliseconds(plan.median)}, {"p99", milliseconds(plan.p99)}}},
      {"frames", run.frames},
      {"local_planner",
       params.local_planner == scenarios::LocalPlanner::dwa ? "dwa" : "pure_pursuit"},
      {"dwa_blocked_steps", result.dwa_blocked_steps},
      {"recoveries", result.recoveries},
      {"recovery_s", result.recovery_seconds},
      {"gave_up", result.gave_up},
      {"gave_up_reason", result.gave_up_reason},
      {"frames_cast", result.frames_cast},
      {"sensors", sensors_json(context.mount_ids, result)},
      {"clearance_margin_m", params.clearance_margin},
      {"goals_reached", result.goals_reached},
      {"goals", result.route_size},
      {"average_speed_m_per_s", result.average_speed},
      {"distance_m", result.distance},
      {"drove_off", result.drove_off},
      {"drop", result.drop_name},
      {"struck_while_standing", result.struck_while_standing},
      {"stops", stops_json(result)},
      {"trajectory", trajectory},
  };
  return summary;
}

void print_costmap_run(const CostmapRun& run, std::ostream& out) {
  const scenarios::ScenarioResult& result = run.result;
  const scenarios::TimeSummary update = scenarios::summarize_times(result.update_seconds);
  const scenarios::TimeSummary plan = scenarios::summarize_times(result.planner_seconds);
  out << run.label << "\n";
  out << "  collision: " << outcome_text(result) << "\n";
  out << "  minimum clearance: "
      << (std::isfinite(result.min_clearance)
              ? fixed(result.min_clearance, 3) + " m (" + result.min_clearance_object +
                    ", t = " + fixed(result.min_clearance_time, 2) + " s)"
              : std::string("no obstacle in the body's height band"))
      << "\n";
  out << "  costmap update: median " << fixed(milliseconds(update.median), 2) << " ms, p99 "
      << fixed(milliseconds(update.p99), 2) << " ms over " << result.updates
      << " updates; planner median " << fixed(milliseconds(plan.median), 2) << " ms, p99 "
      << fixed(milliseconds(plan.p99), 2) << " ms\n";
  if (result.route_size > 1) {
    out << "  goals: " << result.goals_reached << " of " << result.route_size
        << " reached, average speed " << fixed(result.average_speed * 100.0, 1)
        << " cm/s on the way to them, " << fixed(result.distance, 2) << " m driven";
    if (result.struck_while_standing > 0)
      out << "; a walker touched the standing robot " << result.struck_while_standing << " time(s)";
    out << "\n";
    for (std::size_t i = 0; i < result.stops.size(); ++i) {
      const scenarios::StopOutcome& stop = result.stops[i];
      out << "    " << (i + 1) << ". " << stop.name << ": "
          << (stop.reached
                  ? "reached at t = " + fixed(stop.reached_time, 1) + " s (" +
                        fixed(stop.leg_distance, 2) + " m in " + fixed(stop.leg_seconds, 1) + " s)"
                  : stop.reason)
          << "\n";
    }
  }
  if (result.recoveries > 0 || result.dwa_blocked_steps > 0) {
    out << "  deadlock: " << result.recoveries << " recovery(ies), "
        << fixed(result.recovery_seconds, 2) << " s turning; DWA found no admissible velocity at "
        << result.dwa_blocked_steps << " control step(s)"
        << (result.gave_up ? "; " + result.gave_up_reason : "") << "\n";
  }
  out << "  wrote " << run.folder
      << "/summary.json, final.png, master.yaml (+ .pgm), obstacles.yaml (+ .pgm), " << run.frames
      << " frame(s) in frames/\n";
}

void print_costmap_comparison(const std::vector<CostmapRun>& runs, std::ostream& out) {
  TextTable table;
  table.add_column("variant", TextTable::Align::left);
  table.add_column("collision t [s]", TextTable::Align::right);
  table.add_column("object", TextTable::Align::left);
  table.add_column("min clearance [m]", TextTable::Align::right);
  table.add_column("goal", TextTable::Align::left);
  table.add_column("update median [ms]", TextTable::Align::right);
  table.add_column("update p99 [ms]", TextTable::Align::right);
  for (const CostmapRun& run : runs) {
    const scenarios::ScenarioResult& result = run.result;
    const scenarios::TimeSummary update = scenarios::summarize_times(result.update_seconds);
    table.add_row(
        {run.label, result.collided ? fixed(result.collision_time, 2) : "none",
         result.collided ? result.collision_object : "-",
         std::isfinite(result.min_clearance) ? fixed(result.min_clearance, 3) : "-",
         result.reached_goal ? "reached at " + fixed(result.end_time, 1) + " s" : "not reached",
         fixed(milliseconds(update.median), 2), fixed(milliseconds(update.p99), 2)});
  }
  table.print(out, "  ");
}

}  // namespace rigdesign::report
