#include "costmap_variants.hpp"

#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>

#include "progress_line.hpp"
#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/report/text_table.hpp"
#include "rigdesign/scenarios/seed_bootstrap.hpp"

namespace rigdesign::cli {
namespace {

// Paper 2, Table 1 (Elektron: SICK LMS100 and Kinect, 20 repeats each; ../shared/DESIGN.md
// section 9): average speed [m/s] and obstacle critical distance [m].
struct PaperRow {
  const char* variant;
  double speed;
  double critical_distance;
};
constexpr PaperRow kPaper2Table1[] = {
    {"Kinect + lidar", 0.17, 0.05}, {"lidar only", 0.16, 0.20}, {"Kinect only", 0.12, 0.05}};

// The bootstrap's resamples and their generator's seed (fixed: the intervals are part of the
// deterministic output).
constexpr int kBootstrapRounds = 2000;
constexpr std::uint64_t kBootstrapSeed = 54;

bool is_lidar(const model::SensorLibrary& library, const model::Mount& mount) {
  const model::Sensor* sensor = library.find(mount.sensor_id);
  if (!sensor) return false;
  return sensor->technology == model::Technology::lidar_2d ||
         sensor->technology == model::Technology::lidar_3d_spinning ||
         sensor->technology == model::Technology::solid_state_lidar;
}

std::string centimetres(double metres) {
  return report::fixed(metres * 100.0, 1);
}

std::string critical_text(const scenarios::VariantOutcome& outcome,
                          const scenarios::SweepSettings& settings) {
  if (!outcome.skipped.empty()) return "-";
  if (outcome.critical_distance) return centimetres(*outcome.critical_distance);
  return "> " + centimetres(settings.margins.back());
}

std::string below_text(const scenarios::VariantOutcome& outcome) {
  if (!outcome.skipped.empty()) return "skipped: cannot mark the costmap";
  if (outcome.failures.empty()) return "-";
  const scenarios::RunSummary& last = outcome.failures.back();
  return "at " + centimetres(last.margin) + " cm seed " + std::to_string(last.seed) + " hit " +
         last.collision_object + " (t " + report::fixed(last.collision_time, 1) + " s)";
}

nlohmann::json run_json(const scenarios::RunSummary& run) {
  return {
      {"seed", run.seed},
      {"margin_m", run.margin},
      {"collided", run.collided},
      {"collision_object", run.collision_object},
      {"collision_time_s", run.collided ? nlohmann::json(run.collision_time) : nlohmann::json()},
      {"goals_reached", run.goals_reached},
      {"goals_refused", run.goals_refused},
      {"goals", run.goals},
      {"average_speed_m_per_s", run.average_speed},
      {"recovery_s", run.recovery_seconds},
      {"recoveries", run.recoveries},
      {"drove_off", run.drove_off},
      {"drop", run.drop_name},
      {"end_time_s", run.end_time}};
}

nlohmann::json outcome_json(const scenarios::VariantOutcome& outcome) {
  nlohmann::json runs = nlohmann::json::array();
  for (const scenarios::RunSummary& run : outcome.runs) runs.push_back(run_json(run));
  nlohmann::json failures = nlohmann::json::array();
  for (const scenarios::RunSummary& run : outcome.failures) failures.push_back(run_json(run));
  nlohmann::json collided = nlohmann::json::array();  // per margin run, per seed
  for (const std::vector<bool>& margin : outcome.collided_by_margin) collided.push_back(margin);
  const scenarios::VariantMeans means = scenarios::means_of(outcome.runs);
  return {
      {"variant", outcome.variant.label},
      {"clearing_added", outcome.clearing_added},
      {"skipped", outcome.skipped},
      {"critical_distance_m",
       outcome.critical_distance ? nlohmann::json(*outcome.critical_distance) : nlohmann::json()},
      {"mean_average_speed_m_per_s", means.average_speed},
      {"mean_goals_reached", means.goals_reached},
      {"mean_goals_refused", means.goals_refused},
      {"mean_recovery_s", means.recovery_seconds},
      {"drove_off_runs", means.drove_off},
      {"runs_made", outcome.runs_made},
      {"runs", runs},
      {"collisions_below", failures},
      {"collided_by_margin", collided}};
}

// How many seeds collided at each margin run: "0 cm 3/20, 5 cm 1/20, 10 cm 0/20". A seed clear
// at one margin may collide at a larger one: the critical distance rests on the worst seed.
std::string collisions_text(const scenarios::VariantOutcome& outcome,
                            const scenarios::SweepSettings& settings) {
  std::string text;
  for (std::size_t m = 0; m < outcome.collided_by_margin.size(); ++m) {
    const std::vector<bool>& collided = outcome.collided_by_margin[m];
    const auto count = std::count(collided.begin(), collided.end(), true);
    text += (text.empty() ? "" : ", ") + centimetres(settings.margins.at(m)) + " cm " +
            std::to_string(count) + "/" + std::to_string(collided.size());
  }
  return text;
}

// One of paper 2's orderings over seed resamples: the share of resamples in which it holds
// and the 95 % interval of the quantity that must be positive (or zero, `at_least`) for it to.
struct Ordering {
  std::string claim;
  std::function<double(const std::vector<std::size_t>&)> margin_of;  // > 0 (or >= 0): holds
  bool at_least = false;
  std::string unit;  // how the margin prints: "cm/s" or "cm"
};

std::string signed_centimetres(double metres) {
  // A variant collided at every margin tried: its distance is beyond the sweep.
  if (std::isinf(metres)) return metres > 0 ? "+inf (beyond the sweep)" : "-inf (beyond the sweep)";
  return (metres > 0 ? "+" : "") + report::fixed(metres * 100.0, 2);
}

void print_ordering(std::ostream& out, const Ordering& ordering,
                    const std::vector<std::size_t>& all_seeds,
                    const std::vector<std::vector<std::size_t>>& resamples) {
  const auto holds = [&](double margin) { return ordering.at_least ? margin >= 0 : margin > 0; };
  const double observed = ordering.margin_of(all_seeds);
  std::vector<double> margins;
  int held = 0;
  for (const std::vector<std::size_t>& resample : resamples) {
    margins.push_back(ordering.margin_of(resample));
    held += holds(margins.back()) ? 1 : 0;
  }
  const scenarios::Interval interval = scenarios::percentile_interval(margins);
  out << "  " << ordering.claim << ": " << (holds(observed) ? "holds" : "does not hold")
      << " (difference " << signed_centimetres(observed) << " " << ordering.unit
      << ", 95 % bootstrap interval " << signed_centimetres(interval.low) << " to "
      << signed_centimetres(interval.high) << "; holds in "
      << report::fixed(100.0 * held / static_cast<double>(resamples.size()), 1) << " % of "
      << resamples.size() << " resamples of the seeds)\n";
}

// Equal distances beyond the sweep (both infinite) differ by nothing.
double difference(double a, double b) {
  return std::isinf(a) && std::isinf(b) && (a > 0) == (b > 0) ? 0.0 : a - b;
}

// Paper 2's qualitative outcome, for a rig of one lidar and one camera: the whole rig first,
// then each mount alone (rig_variants' order for two mounts), each ordering with a paired
// bootstrap over the seeds (issue 54: reported whether or not it holds).
void print_paper2_checks(std::ostream& out, const RigInputs& inputs,
                         const std::vector<scenarios::VariantOutcome>& outcomes,
                         const scenarios::SweepSettings& settings) {
  const model::Rig& rig = inputs.rig;
  if (rig.mounts.size() != 2 || outcomes.size() != 3) return;
  const bool first_lidar = is_lidar(inputs.library, rig.mounts[0]);
  if (first_lidar == is_lidar(inputs.library, rig.mounts[1])) return;
  const scenarios::VariantOutcome& both = outcomes[0];
  const scenarios::VariantOutcome& lidar = outcomes[first_lidar ? 1 : 2];
  const scenarios::VariantOutcome& camera = outcomes[first_lidar ? 2 : 1];
  if (!both.skipped.empty() || !lidar.skipped.empty() || !camera.skipped.empty()) return;
  using Picked = std::vector<std::size_t>;
  const auto speed = [](const scenarios::VariantOutcome& o) {
    return [&o](const Picked& p) { return scenarios::resampled_average_speed(o, p); };
  };
  const auto critical = [&](const scenarios::VariantOutcome& o) {
    return [&o, &settings](const Picked& p) {
      return scenarios::resampled_critical_distance(o, settings.margins, p);
    };
  };
  const auto v_both = speed(both), v_lidar = speed(lidar), v_camera = speed(camera);
  const auto d_both = critical(both), d_lidar = critical(lidar), d_camera = critical(camera);
  const std::vector<Ordering> orderings = {
      {"lidar only faster than camera only",
       [&](const Picked& p) { return v_lidar(p) - v_camera(p); }, false, "cm/s"},
      {"camera's critical distance smaller than the lidar's",
       [&](const Picked& p) { return difference(d_lidar(p), d_camera(p)); }, false, "cm"},
      {"both at least as fast as the faster alone",
       [&](const Picked& p) { return v_both(p) - std::max(v_lidar(p), v_camera(p)); }, true,
       "cm/s"},
      {"both as close as the closer alone",
       [&](const Picked& p) { return difference(std::min(d_lidar(p), d_camera(p)), d_both(p)); },
       true, "cm"}};
  Picked all_seeds(both.runs.size());
  for (std::size_t i = 0; i < all_seeds.size(); ++i) all_seeds[i] = i;
  const std::vector<Picked> resamples =
      scenarios::seed_resamples(all_seeds.size(), kBootstrapRounds, kBootstrapSeed);
  out << "paper 2's qualitative outcome (lidar " << lidar.variant.label << ", camera "
      << camera.variant.label << "), each with a paired bootstrap over the seeds ("
      << kBootstrapRounds << " resamples, seed " << kBootstrapSeed << "):\n";
  for (const Ordering& ordering : orderings) print_ordering(out, ordering, all_seeds, resamples);
}

}  // namespace

void run_costmap_variants(std::ostream& out, std::ostream& err, const RigInputs& inputs,
                          const scenarios::ScenarioFactory& make_scenario,
                          const scenarios::ScenarioParams& params,
                          const scenarios::SweepSettings& settings, const std::string& folder) {
  const std::vector<scenarios::RigVariant> variants = scenarios::rig_variants(inputs.rig);
  std::string margins;
  for (const double m : settings.margins)
    margins += (margins.empty() ? "" : ", ") + model::format_number(m);
  out << "rig variants, seeds " << settings.first_seed << " to "
      << settings.first_seed + static_cast<std::uint64_t>(settings.seeds) - 1
      << " each; critical distance: the smallest clearance margin (" << margins
      << " m) at which no run collides; the table's means are over the runs at that margin\n";
  const auto start = std::chrono::steady_clock::now();
  std::vector<scenarios::VariantOutcome> outcomes;
  int runs = 0;
  {
    ProgressLine progress(err, "costmap variants", "runs");
    for (const scenarios::RigVariant& variant : variants) {
      progress.retitle("costmap variants: " + variant.label);
      outcomes.push_back(scenarios::sweep_variant(
          make_scenario, inputs.rig, inputs.library, params, variant, settings,
          [&](const scenarios::RunSummary& run) {
            ++runs;
            progress.update(runs, static_cast<double>(variants.size()) * settings.seeds,
                            "margin " + model::format_number(run.margin) + " m, seed " +
                                std::to_string(run.seed));
          }));
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report::TextTable table;
  table.add_column("variant", report::TextTable::Align::left);
  table.add_column("critical distance [cm]", report::TextTable::Align::right);
  table.add_column("avg speed [cm/s]", report::TextTable::Align::right);
  table.add_column("goals reached", report::TextTable::Align::right);
  table.add_column("refused", report::TextTable::Align::right);
  table.add_column("recovery [s]", report::TextTable::Align::right);
  table.add_column("drove off", report::TextTable::Align::right);
  table.add_column("collision just below", report::TextTable::Align::left);
  table.add_column("seeds colliding at each margin", report::TextTable::Align::left);
  nlohmann::json outcomes_json = nlohmann::json::array();
  for (const scenarios::VariantOutcome& outcome : outcomes) {
    const scenarios::VariantMeans means = scenarios::means_of(outcome.runs);
    const std::string of =
        outcome.runs.empty() ? "" : " of " + std::to_string(outcome.runs.front().goals);
    const bool ran = outcome.skipped.empty();
    table.add_row(
        {outcome.variant.label, critical_text(outcome, settings),
         ran ? centimetres(means.average_speed) : "-",
         ran ? report::fixed(means.goals_reached, 2) + of : "-",
         ran ? report::fixed(means.goals_refused, 2) : "-",
         ran ? report::fixed(means.recovery_seconds, 1) : "-",
         ran ? std::to_string(means.drove_off) + "/" + std::to_string(outcome.runs.size()) : "-",
         below_text(outcome), ran ? collisions_text(outcome, settings) : "-"});
    outcomes_json.push_back(outcome_json(outcome));
  }
  table.print(out, "  ");
  for (const scenarios::VariantOutcome& outcome : outcomes) {
    if (outcome.clearing_added)
      out << "  " << outcome.variant.label
          << ": none of its sources clears, so each clears too (a costmap nothing clears keeps "
             "every mark)\n";
  }
  out << "paper 2, Table 1 (Elektron, SICK LMS100 270 deg + Kinect 57 deg, office and workshop, "
         "20 repeats):\n";
  report::TextTable paper;
  paper.add_column("variant", report::TextTable::Align::left);
  paper.add_column("critical distance [cm]", report::TextTable::Align::right);
  paper.add_column("avg speed [cm/s]", report::TextTable::Align::right);
  for (const PaperRow& row : kPaper2Table1) {
    paper.add_row({row.variant, centimetres(row.critical_distance), centimetres(row.speed)});
  }
  paper.print(out, "  ");
  print_paper2_checks(out, inputs, outcomes, settings);
  int made = 0;
  for (const scenarios::VariantOutcome& outcome : outcomes) made += outcome.runs_made;
  out << "  " << made << " runs in " << report::fixed(seconds, 1) << " s on " << settings.threads
      << " thread(s)\n";
  io::write_file_atomically(folder + "/variants.json", outcomes_json.dump(2) + "\n");
  out << "  wrote " << folder << "/variants.json\n";
}

}  // namespace rigdesign::cli
