// Reports are data rendered by separate writers (issue 29, item 3): one report, built by hand
// here, states the same numbers in every format. Expected texts follow from the inputs and
// the documented formats (fixed decimals, 3 or 4 significant digits), not from a run.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "rigdesign/report/check_github.hpp"
#include "rigdesign/report/check_json.hpp"
#include "rigdesign/report/check_junit.hpp"
#include "rigdesign/report/check_text.hpp"
#include "rigdesign/report/filter_json.hpp"
#include "rigdesign/report/filter_text.hpp"
#include "rigdesign/report/localize_json.hpp"
#include "rigdesign/report/localize_text.hpp"
#include "rigdesign/report/requirement_text.hpp"
#include "rigdesign/report/select_html.hpp"
#include "rigdesign/report/select_json.hpp"
#include "rigdesign/report/select_text.hpp"

using namespace rigdesign;
using nlohmann::json;

namespace {

std::size_t occurrences(const std::string& text, const std::string& part) {
  std::size_t count = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1))
    ++count;
  return count;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

metrics::RequirementResult requirement(std::string id, std::string metric,
                                       metrics::Verdict verdict) {
  metrics::RequirementResult result;
  result.id = std::move(id);
  result.title = "title of " + result.id;
  result.metric = std::move(metric);
  result.verdict = verdict;
  result.explanation = "why " + result.id;
  result.field = "field_" + result.id;
  return result;
}

// A rig with one requirement of each verdict and one warning.
report::FileReport judged_rig() {
  report::FileReport report;
  report.file = "rig.yaml";
  report.kind = io::FileKind::rig;
  report.summary = "rig 'Test' is valid: 1 mounts";
  report.diagnostics.push_back(
      {{"rig.yaml", 3, 1}, "mounts[0]", "is close to the body", "", model::Severity::warning});
  metrics::RequirementResult met = requirement("R3", "F", metrics::Verdict::pass);
  met.unit = "Hz";
  met.required = 10;
  met.actual = 15;
  met.bound = metrics::Bound::at_least;
  met.where = {"req.yaml", 4, 3};
  metrics::RequirementResult missed = requirement("R2", "SC", metrics::Verdict::fail);
  missed.required = 0.75;
  missed.actual = 0.4;
  missed.bound = metrics::Bound::at_least;
  missed.where = {"req.yaml", 7, 5};
  missed.rig_where = {"rig.yaml", 2, 1};
  missed.limiting_mounts = {"front"};
  metrics::RequirementResult skipped = requirement("R8", "L", metrics::Verdict::not_evaluated);
  skipped.where = {"req.yaml", 9, 3};
  report.results = {met, missed, skipped};
  report.load_seconds = 0.25;
  report.result_seconds = {0.5, 0.25, 0.0};
  return report;
}

}  // namespace

TEST_CASE("check: one file report gives the same verdicts in text, JSON, JUnit and GitHub",
          "[report]") {
  const std::vector<report::FileReport> reports = {judged_rig()};
  // SC shares read as percent: 40 - 75 = -35 points, -35 / 75 = -46.7 %.
  CHECK(report::measured_text(reports[0].results[1]) ==
        "SC = 40 %, required >= 75 %, margin -35 % (-46.7 %)");
  CHECK(report::measured_text(reports[0].results[2]).empty());

  const std::string text = report::format_text(reports);
  CHECK(contains(text, "rig.yaml: rig 'Test' is valid: 1 mounts\n"));
  CHECK(contains(text, "rig.yaml:2:1: field_R2: fail: R2 title of R2: SC = 40 %"));
  const std::string summary =
      "check: 1 file(s), 0 invalid; requirements: 1 pass, 1 fail, 1 not evaluated\n";
  CHECK(text.size() >= summary.size());
  CHECK(text.substr(text.size() - summary.size()) == summary);

  const json document = json::parse(report::format_json(reports, 1));
  CHECK(document["exit_code"] == 1);
  const json& file = document["files"][0];
  CHECK(file["status"] == "fail");
  REQUIRE(file["requirements"].size() == 3);
  CHECK(file["requirements"][0]["verdict"] == "pass");
  CHECK(file["requirements"][1]["actual"] == 0.4);
  CHECK(file["requirements"][2]["verdict"] == "not evaluated");
  CHECK(file["diagnostics"].size() == 1);

  // 1 validity case + 3 requirements; time 0.25 + 0.5 + 0.25 + 0 s.
  const std::string junit = report::format_junit(reports);
  CHECK(occurrences(junit, "tests=\"4\" failures=\"1\" errors=\"0\" skipped=\"1\"") == 2);
  CHECK(contains(junit,
                 "<testsuite name=\"rig.yaml\" tests=\"4\" failures=\"1\" errors=\"0\" "
                 "skipped=\"1\" time=\"1.000000\">"));
  CHECK(occurrences(junit, "<failure type=\"requirement\"") == 1);
  CHECK(contains(junit, "<skipped message=\"why R8\"/>"));

  const std::string github = report::format_github(reports);
  CHECK(occurrences(github, "::error ") == 1);
  CHECK(occurrences(github, "::warning ") == 1);
  CHECK(contains(github, "::error file=rig.yaml,line=2,col=1,title=rigdesign R2 title of R2::"));
  CHECK(github.substr(github.size() - summary.size()) == summary);
}

TEST_CASE("localize: an emitter and a CO2 log give the same numbers as text and JSON",
          "[report][localize]") {
  report::EmitterReport emitter;
  emitter.method = localize::LocalizeMethod::wls;
  emitter.estimate.bssid = "02:00:00:00:00:01";
  emitter.estimate.readings = 120;
  emitter.estimate.used = 96;
  emitter.estimate.chunks.resize(4);
  emitter.estimate.geometry.dimensions = 2;
  localize::Hypothesis h;
  h.position = {1.5, -2.25, 0.8};
  h.covariance.diagonal() << 0.25, 0.09, 0.0;
  h.rssi_at_1m_dbm = -45.3;
  h.exponent = 2.5;
  emitter.estimate.hypotheses = {h};
  emitter.truth = model::Vec3(1.5, -1.25, 0.8);
  localize::EmitterKpis kpis;
  kpis.final_error = 1.0;  // the truth is 1 m from the estimate along y
  kpis.nearest_hypothesis_error = 1.0;
  kpis.expected_error = 1.0;
  kpis.in_region = true;
  kpis.detected = true;
  emitter.kpis = kpis;

  localize::GasDetection detection;
  detection.index = 102;
  detection.trigger_index = 100;
  detection.position = {10.2, -0.18, 0.3};
  detection.lag_corrected = {9.0, -0.2, 0.3};
  detection.ppm = 2931;
  detection.threshold_ppm = 1800;
  localize::GasScore score;
  score.true_detections = 1;
  localize::GasArtifactResult found;
  found.artifact.id = 1;
  found.path_distance = 0.7;
  found.nearest_detection = 0.7;
  found.found = true;
  score.artifacts = {found};
  report::GasReport gas{"trace.txt", 300, false, 6.0, {}};
  gas.modes.push_back({localize::GasThreshold::fixed, {detection}, score, score});
  gas.modes.push_back({localize::GasThreshold::relative, {}, std::nullopt, std::nullopt});

  report::LogsReport logs;
  logs.logs.push_back({"walk.csv", 120, 1, {emitter}, std::nullopt});
  logs.logs.push_back({"trace.txt", 300, 0, {}, gas});
  const report::LocalizeOptions options;  // cut-off -80 dBm, 1 s per untimed reading
  std::ostringstream out;
  for (const report::LogReport& log : logs.logs) report::print_log(log, options, out);
  const std::string text = out.str();
  CHECK(contains(text, "walk.csv: 120 readings of 1 emitter(s)\n"));
  CHECK(contains(text,
                 "emitter 02:00:00:00:00:01 (wls): 120 log lines, 96 heard above "
                 "-80 dBm (paper 4's cut-off), 4 chunks\n"));
  // sd = sqrt of the covariance's diagonal: 0.5 and 0.3 m.
  CHECK(contains(text, "  estimate (1.50, -2.25) m, sd x 0.50 y 0.30 m, a -45.3 dBm, n 2.50\n"));
  CHECK(contains(text,
                 "  truth (1.50, -1.25): error 1.00 m (nearest hypothesis 1.00 m, "
                 "probability-weighted 1.00 m); inside the stated 95 % region; detected\n"));
  CHECK(contains(text,
                 "trace.txt: 300 CO2 readings (untimed: 1 s per reading assumed), lag "
                 "correction 6.0 s\n"));
  CHECK(contains(text,
                 "    reading 102 at (10.20, -0.18): 2931 ppm (threshold 1800), "
                 "lag-corrected (9.00, -0.20)\n"));
  CHECK(occurrences(text,
                    ": 1 within 5 m of a gas artifact, 0 not; gas 1 found (path passes "
                    "0.7 m, nearest detection 0.7 m)\n") == 2);
  CHECK(contains(text, "  threshold relative (median + 6 MAD, >= 50 ppm rise): 0 detection(s)\n"));

  const json document = report::to_json(logs);
  const json& located = document["logs"][0]["emitters"][0];
  CHECK(located["method"] == "wls");
  CHECK(located["used"] == 96);
  CHECK(located["chunks"] == 4);
  CHECK(located["hypotheses"][0]["position"] == json({1.5, -2.25, 0.8}));
  CHECK(located["hypotheses"][0]["covariance"][1][1] == 0.09);
  CHECK(located["truth"] == json({1.5, -1.25, 0.8}));
  CHECK(located["kpis"]["error_m"] == 1.0);
  CHECK_FALSE(located.contains("scans"));  // only the range fit reports its scans
  const json& co2 = document["logs"][1];
  CHECK(co2["timed"] == false);
  CHECK(co2["lag_s"] == 6.0);
  CHECK(co2["modes"][0]["detections"][0]["index"] == 102);
  CHECK(co2["modes"][0]["detections"][0]["ppm"] == 2931.0);
  CHECK(co2["modes"][0]["score"]["true_detections"] == 1);
  CHECK(co2["modes"][0]["score_lag_corrected"]["artifacts"][0]["found"] == true);
  CHECK(co2["modes"][1]["detections"].empty());
  CHECK_FALSE(co2["modes"][1].contains("score"));
}

TEST_CASE("select: a relaxation trace gives the same costs in text, JSON and HTML",
          "[report][select]") {
  model::Sensor sensor;
  sensor.id = "cam";
  model::SensorMode mode;
  mode.id = "m30";
  model::Catalog catalog;
  catalog.name = "Small";
  catalog.file = "small.yaml";
  catalog.sensors.resize(1);
  model::MountingSlot slot;
  slot.id = "front";
  slot.poses.resize(1);  // a fixed pose: no label
  catalog.slots = {slot};
  select::CatalogOption option;
  option.sensor = &sensor;
  option.mode = &mode;
  model::Requirements requirements;
  requirements.name = "App";
  requirements.file = "app.yaml";
  const model::RelaxationPolicy no_policy;

  select::RelaxationOutcome outcome;
  outcome.iterations.resize(2);
  select::RelaxationIteration& first = outcome.iterations[0];
  first.targets.min_frequency = 20;
  first.targets.max_spacing = 0.15;
  first.selection.infeasible_reason = "no combination meets every requirement";
  select::RelaxationIteration& relaxed = outcome.iterations[1];
  relaxed.relaxed = "robot_speed.max_speed 1 -> 0.5 m/s";
  relaxed.targets.min_frequency = 10;
  relaxed.targets.max_spacing = 0.15;
  relaxed.within_budget = true;
  select::Selection& rig = relaxed.selection;
  rig.found = true;
  rig.chosen = {&option};
  rig.cost = {true, 1000, 34, 200, 1234, "usb", "pc"};
  rig.search.nodes = 5;
  rig.coverage.complete.mean = 0.368;
  rig.coverage.floor.mean = 0.47;
  outcome.within_budget = true;
  const report::SelectReport report{&catalog,
                                    1,
                                    &requirements,
                                    &no_policy,
                                    2000,
                                    &outcome,
                                    {"out/chosen_rig.yaml", "out/pareto.png"},
                                    {},
                                    {},
                                    {"deploy/collision_monitor.yaml: warning: stop: 0.1 m of its "
                                     "2 m boundary is seen by no source"},
                                    "rigdesign check out/chosen_rig.yaml --requirements x",
                                    30,
                                    1,
                                    {"B2 housing clear of body and sensors: front: cuts 3 mm"},
                                    {},
                                    {},
                                    {},
                                    0.0};

  CHECK(report::chosen_iteration(outcome) == &relaxed);
  CHECK(report::describe(relaxed.targets) == "F >= 10 Hz, R <= 150 mm");
  std::ostringstream out;
  report::print_select_iteration(report, 1, relaxed, out);
  report::print_select_summary(report, out);
  const std::string text = out.str();
  CHECK(contains(text,
                 "#1  relaxed robot_speed.max_speed 1 -> 0.5 m/s\n"
                 "    needs: F >= 10 Hz, R <= 150 mm\n"
                 "    cheapest rig: 1234 USD = sensors 1000 + transfer 34 (usb) + CPU 200 "
                 "(pc)  WITHIN BUDGET\n      front: cam/m30\n    search: 5 nodes"));
  CHECK(contains(text, "\nChosen rig (1234 USD <= budget 2000 USD): front: cam/m30\n"));
  CHECK(contains(text, "  SC complete mean 36.8 %, floor mean 47 % (exact path)\n"));
  // What passes is check's own verdict on the files written (issue 52 item 6), failures listed.
  CHECK(contains(text,
                 "\nwrote 2 files in out\nchecked them: `rigdesign check "
                 "out/chosen_rig.yaml --requirements x`: 30 pass, 1 fail\n"
                 "  B2 housing clear of body and sensors: front: cuts 3 mm\n"));
  // The deployment's own warning, said in the main job's output (issue 52 item 6).
  CHECK(contains(text, "deploy/collision_monitor.yaml: warning: stop: 0.1 m of its 2 m"));

  const json document = report::to_json(report);
  CHECK(document["within_budget"] == true);
  CHECK(document["budget"] == 2000.0);
  CHECK(document["iterations"][0]["found"] == false);
  CHECK(document["iterations"][0]["reason"] == "no combination meets every requirement");
  const json& chosen = document["iterations"][1];
  CHECK(chosen["needs"] == "F >= 10 Hz, R <= 150 mm");
  CHECK(chosen["cost"]["total"] == 1234.0);
  CHECK(chosen["cost"]["transfer_id"] == "usb");
  CHECK(chosen["rig"] ==
        json::parse(R"([{"slot":"front","sensor":"cam","mode":"m30","pose":""}])"));
  CHECK(document["files"].size() == 2);

  const std::string html = report::selection_trace_html(report, relaxed, "<svg></svg>");
  CHECK(contains(html, "<td>1234</td><td class=\"text pass\">yes</td><td>5</td>"));
  CHECK(contains(html, "<td>none</td><td class=\"text fail\">no</td>"));
  CHECK(contains(html, "<td class=\"text\">transfer: usb</td><td>34</td>"));
  CHECK(contains(html, "<th class=\"text\">total</th><th>1234</th>"));
  CHECK(contains(html, "<p>front: cam/m30</p>"));
}

TEST_CASE("filter: a mount's load gives the same numbers as text and JSON", "[cli]") {
  report::FilterSceneReport report;
  report.rig_name = "Cart";
  report.scene = "office";
  report.pipeline = "P4";
  report.frames = 3;
  // 30 Hz, 20,000 of 100,000 points kept, 4 ms median per frame: U_f = 0.004 x 30 = 0.12 cores,
  // 0.004 / 100,000 = 4e-08 s per point.
  report.mounts.push_back({"front", 30.0, 100000, 20000, {0.004, 0.005}, {0.12, 4e-08}});
  report.total_load_cores = 0.12;
  report.loads_file = "loads.yaml";
  std::ostringstream text;
  report::print_filter_scene(report, text);
  CHECK(contains(text.str(), "Cart in the office scene, pipeline P4, 3 frames per sensor"));
  CHECK(contains(text.str(), "100000"));
  CHECK(contains(text.str(), "20000"));
  CHECK(contains(text.str(), "4.00"));   // median ms, two decimals
  CHECK(contains(text.str(), "5.00"));   // p95 ms
  CHECK(contains(text.str(), "0.120"));  // cores, three decimals
  CHECK(contains(text.str(), "4e-08"));  // s per point, 3 significant digits
  CHECK(contains(text.str(), "U_f = 0.120 core-equivalents"));
  CHECK(contains(text.str(), "wrote the loads per sensor to loads.yaml"));
  const json j = report::filter_scene_json(report);
  CHECK(j["mounts"][0]["mount"] == "front");
  CHECK(j["mounts"][0]["points_per_frame"] == 100000);
  CHECK(j["mounts"][0]["median_s"].get<double>() == Approx(0.004));
  CHECK(j["mounts"][0]["filtering_load_cores"].get<double>() == Approx(0.12));
  CHECK(j["mounts"][0]["filtering_seconds_per_point"].get<double>() == Approx(4e-08));
  CHECK(j["total_filtering_load_cores"].get<double>() == Approx(0.12));
  CHECK(j["frames"] == 3);
}
