#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign::test;

TEST_CASE("localize: bad logs exit 2 naming file:line:column and the column", "[localize]") {
  TempFolder folder;
  const std::string missing = folder.write("missing.csv", "t,x,y,z,bssid\n0,0,0,0,a\n");
  CliResult result = run_cli({"localize", "--log", missing});
  CHECK(result.exit_code == 2);
  CHECK(result.err.find(missing + ":1:1: rssi: column is missing") != std::string::npos);
  const std::string text =
      folder.write("text.csv", "t,x,y,z,bssid,rssi\n0,0,0,0,a,-50\n0,0,0,0,a,strong\n");
  result = run_cli({"localize", "--log", text});
  CHECK(result.exit_code == 2);
  CHECK(result.err.find(text + ":3:11: rssi: 'strong' is not a number") != std::string::npos);
  const std::string positive = folder.write("positive.csv", "t,x,y,z,bssid,rssi\n0,0,0,0,a,12\n");
  result = run_cli({"localize", "--log", positive});
  CHECK(result.exit_code == 2);
  CHECK(result.err.find("above 0 dBm") != std::string::npos);
  const std::string empty = folder.write("empty.csv", "");
  CHECK(run_cli({"localize", "--log", empty}).exit_code == 2);
  result = run_cli({"localize", "--scenario", "cave"});
  CHECK(result.exit_code == 2);
  CHECK(result.err.find("unknown scenario 'cave'") != std::string::npos);
  CHECK(run_cli({"localize"}).exit_code == 2);
  CHECK(run_cli({"localize", "--scenario", "loop", "--method", "magic"}).exit_code == 2);
}

TEST_CASE("localize: a scenario written out reads back to the same estimate, with KPIs and plots",
          "[localize]") {
  TempFolder folder;
  const CliResult generated = run_cli({"localize", "--scenario", "corner", "--seed", "3",
                                       "--checkpoints", "5", "--json", "--out", folder.path()});
  INFO(generated.err);
  REQUIRE(generated.exit_code == 0);
  const auto report = nlohmann::json::parse(generated.out);
  const auto& emitter = report["emitters"][0];
  CHECK(emitter["method"] == "nls");
  CHECK(emitter["kpis"]["error_m"].get<double>() >= 0.0);
  CHECK(emitter["geometry"]["z_observable"] == false);
  for (const char* file : {"corner_seed3.png", "corner_seed3.svg", "corner_seed3_rssi.csv",
                           "corner_seed3_truth.csv"}) {
    CHECK(std::filesystem::exists(folder.path() + "/" + file));
  }
  const CliResult read =
      run_cli({"localize", "--log", folder.path() + "/corner_seed3_rssi.csv", "--truth",
               folder.path() + "/corner_seed3_truth.csv", "--checkpoints", "5", "--json"});
  REQUIRE(read.exit_code == 0);
  const auto again = nlohmann::json::parse(read.out)["logs"][0]["emitters"][0];
  for (int k = 0; k < 2; ++k) {
    CHECK(again["hypotheses"][0]["position"][k].get<double>() ==
          Approx(emitter["hypotheses"][0]["position"][k].get<double>()).margin(1e-4));
  }
  CHECK(again["kpis"]["error_m"].get<double>() ==
        Approx(emitter["kpis"]["error_m"].get<double>()).margin(1e-4));
}

TEST_CASE("localize: the straight hallway is reported with two mirror hypotheses", "[localize]") {
  const CliResult result = run_cli({"localize", "--scenario", "hallway", "--seed", "2"});
  REQUIRE(result.exit_code == 0);
  CHECK(result.out.find("collinear") != std::string::npos);
  CHECK(result.out.find("ambiguous: hypotheses 1 and 2 are indistinguishable") !=
        std::string::npos);
  const CliResult left =
      run_cli({"localize", "--scenario", "hallway", "--seed", "2", "--prefer-side", "left"});
  REQUIRE(left.exit_code == 0);
  CHECK(left.out.find("listed by --prefer-side left") != std::string::npos);
  const std::size_t first = left.out.find("hypothesis 1 (p ");
  REQUIRE(first != std::string::npos);
  CHECK(left.out.substr(first, left.out.find('\n', first) - first).find("left of the path") !=
        std::string::npos);
  const CliResult bad = run_cli({"localize", "--scenario", "hallway", "--prefer-side", "up"});
  CHECK(bad.exit_code == 2);
  CHECK(bad.err.find("--prefer-side") != std::string::npos);
}

TEST_CASE("localize: the bundled example log reads and its phone is found within 5 m",
          "[localize]") {
  const CliResult result =
      run_cli({"localize", "--log", source_path("data/localize/corner_rssi.csv"), "--truth",
               source_path("data/localize/corner_truth.csv"), "--method", "all", "--checkpoints",
               "5", "--json"});
  INFO(result.err);
  REQUIRE(result.exit_code == 0);
  const auto emitters = nlohmann::json::parse(result.out)["logs"][0]["emitters"];
  REQUIRE(emitters.size() == 3);  // wls, nls, map
  CHECK(emitters[1]["method"] == "nls");
  CHECK(emitters[1]["kpis"]["detected"] == true);
}

namespace {

// The log with every position moved by (dx, dy): UTM eastings and northings.
std::string shifted_log(const std::string& csv, double dx, double dy) {
  std::istringstream lines(csv);
  std::string line, result;
  std::getline(lines, line);
  result = line + "\n";  // t,x,y,z,bssid,rssi
  while (std::getline(lines, line)) {
    std::vector<std::string> cells;
    std::stringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    REQUIRE(cells.size() == 6);
    std::ostringstream moved;
    moved.precision(17);
    moved << cells[0] << ',' << std::stod(cells[1]) + dx << ',' << std::stod(cells[2]) + dy << ','
          << cells[3] << ',' << cells[4] << ',' << cells[5] << '\n';
    result += moved.str();
  }
  return result;
}

}  // namespace

TEST_CASE("localize: a log in UTM coordinates gives the same estimate, moved (issue 16)",
          "[localize]") {
  // Issue 16: x near 1e7 overflowed a signed cell key (UBSan) and still returned a result.
  const double dx = 5.5e6, dy = 9.9e6;  // a northing near UTM's upper end
  TempFolder folder;
  std::ifstream stream(source_path("data/localize/corner_rssi.csv"));
  std::stringstream original;
  original << stream.rdbuf();
  const std::string moved = folder.write("utm.csv", shifted_log(original.str(), dx, dy));
  const auto estimate = [](const std::string& log) {
    const CliResult result = run_cli({"localize", "--log", log, "--json"});
    INFO(result.err);
    REQUIRE(result.exit_code == 0);
    const nlohmann::json json = nlohmann::json::parse(result.out);
    return json["logs"][0]["emitters"][0]["hypotheses"][0]["position"];
  };
  const nlohmann::json local = estimate(source_path("data/localize/corner_rssi.csv"));
  const nlohmann::json utm = estimate(moved);
  // Positions near 1e7 m carry about 2e-9 m of double rounding per reading: the fit moves
  // by far less than a centimetre.
  CHECK(utm[0].get<double>() - dx == Approx(local[0].get<double>()).margin(0.01));
  CHECK(utm[1].get<double>() - dy == Approx(local[1].get<double>()).margin(0.01));
}

TEST_CASE("localize --search-area: the estimate lies in the area the user searches (issue 33)",
          "[localize]") {
  // The loop scenario's phone stands near (1.0, -0.8) (docs/localize.md). A search area that
  // leaves it out must still give hypotheses inside the area (a uniform prior there, none
  // outside); one that holds it must give the first hypothesis inside too.
  TempFolder folder;
  REQUIRE(run_cli({"localize", "--scenario", "loop", "--seed", "2", "--out", folder.path()})
              .exit_code == 0);
  const std::string log = folder.path() + "/loop_seed2_rssi.csv";
  for (const std::array<double, 4>& area :
       {std::array<double, 4>{-20, -20, 20, 20}, std::array<double, 4>{5, 5, 15, 15}}) {
    std::vector<std::string> args = {"localize", "--log", log, "--json", "--search-area"};
    for (const double v : area) args.push_back(std::to_string(v));
    const CliResult result = run_cli(args);
    INFO(result.out << result.err);
    REQUIRE(result.exit_code == 0);
    const auto hypotheses =
        nlohmann::json::parse(result.out)["logs"][0]["emitters"][0]["hypotheses"];
    REQUIRE(!hypotheses.empty());
    for (const auto& hypothesis : hypotheses) {
      const double x = hypothesis["position"][0].get<double>();
      const double y = hypothesis["position"][1].get<double>();
      CHECK(x >= area[0] - 1e-9);
      CHECK(x <= area[2] + 1e-9);
      CHECK(y >= area[1] - 1e-9);
      CHECK(y <= area[3] + 1e-9);
    }
  }
}

TEST_CASE("localize --calibrate fits the level and exponent of a log whose phone is known",
          "[localize]") {
  // rssi = -50 - 30 log10 d, read 1 dB high and 1 dB low at 2, 4, 8, 16 and 32 m: the fit is
  // that line (least squares, all heard), sigma 1 dB.
  TempFolder folder;
  std::ostringstream log;
  log << "t,x,y,z,bssid,rssi\n";
  int t = 0;
  for (const double d : {2.0, 4.0, 8.0, 16.0, 32.0}) {
    for (const double e : {1.0, -1.0}) {
      const double rssi = -50.0 - 30.0 * std::log10(d) + e;
      log << t++ << "," << d << ",0,0.4,aa:bb:cc:dd:ee:01," << rssi << "\n";
    }
  }
  const std::string log_path = folder.write("calibration.csv", log.str());
  const std::string truth = folder.write("truth.csv", "bssid,x,y,z\naa:bb:cc:dd:ee:01,0,0,0.4\n");
  CliResult result =
      run_cli({"localize", "--calibrate", "--log", log_path, "--truth", truth, "--json"});
  INFO(result.out << result.err);
  REQUIRE(result.exit_code == 0);
  const auto fit = nlohmann::json::parse(result.out)["calibrations"][0];
  CHECK(fit["rssi_at_1m_dbm"].get<double>() == Approx(-50.0).margin(0.01));
  CHECK(fit["exponent"].get<double>() == Approx(3.0).margin(0.001));
  CHECK(fit["sigma_db"].get<double>() == Approx(1.0).margin(0.001));
  CHECK(fit["heard"].get<int>() == 10);
  result = run_cli({"localize", "--calibrate", "--log", log_path, "--truth", truth});
  CHECK(result.out.find("use: --rssi-at-1m -50 --exponent 3") != std::string::npos);
  // Without the phone's position there is nothing to calibrate against.
  result = run_cli({"localize", "--calibrate", "--log", log_path});
  CHECK(result.exit_code == 2);
  CHECK(result.err.find("--calibrate: needs the emitters' positions") != std::string::npos);
}

TEST_CASE("localize --environment sets paper 4's Table 4 exponent, bad names and weightings exit 2",
          "[localize]") {
  TempFolder folder;
  REQUIRE(run_cli({"localize", "--scenario", "corner", "--seed", "1", "--out", folder.path()})
              .exit_code == 0);
  const std::string log = folder.path() + "/corner_seed1_rssi.csv";
  CliResult result = run_cli(
      {"localize", "--log", log, "--method", "wls", "--environment", "indoor-general", "--json"});
  INFO(result.out << result.err);
  REQUIRE(result.exit_code == 0);
  // Paper 4's Table 4, "Indoor general, 4 to 6": 5.
  CHECK(nlohmann::json::parse(result.out)["logs"][0]["emitters"][0]["hypotheses"][0]["exponent"]
            .get<double>() == 5.0);
  // Its "Indoor through floor, 3 to 6": 4.5.
  result = run_cli({"localize", "--log", log, "--method", "wls", "--environment",
                    "indoor-through-floor", "--json"});
  REQUIRE(result.exit_code == 0);
  CHECK(nlohmann::json::parse(result.out)["logs"][0]["emitters"][0]["hypotheses"][0]["exponent"]
            .get<double>() == 4.5);
  // Eq. 12 as printed is an option and the report says which weighting ran.
  result = run_cli({"localize", "--log", log, "--method", "wls", "--wls-weighting", "paper"});
  REQUIRE(result.exit_code == 0);
  CHECK(result.out.find("right-hand side only (eq. 12 as printed") != std::string::npos);
  result = run_cli({"localize", "--log", log, "--method", "wls"});
  CHECK(result.out.find("on both sides of each equation (eq. 12 as weighted least squares)") !=
        std::string::npos);
  result = run_cli({"localize", "--log", log, "--environment", "attic"});
  CHECK(result.exit_code == 2);
  CHECK(result.err.find("--environment: is 'attic' (expected one of free-space") !=
        std::string::npos);
  result = run_cli({"localize", "--log", log, "--wls-weighting", "squares"});
  CHECK(result.exit_code == 2);
  CHECK(result.err.find("--wls-weighting: is 'squares' (expected paper, rows or residuals)") !=
        std::string::npos);
  CHECK(run_cli({"localize", "--log", log, "--environment", "free-space", "--exponent", "2"})
            .exit_code == 2);
}

TEST_CASE("localize on a CO2 log detects as paper 4's ground robot unless told otherwise",
          "[localize]") {
  // 1 reading a second and a metre along x; 2500 ppm at x = 10..12 over 450 ppm.
  TempFolder folder;
  std::string text = "t,x,y,z,co2_ppm\n";
  for (int i = 0; i < 30; ++i) {
    text += std::to_string(i) + "," + std::to_string(i) + ",0,0.3," +
            (i >= 10 && i <= 12 ? "2500" : "450") + "\n";
  }
  const std::string log = folder.write("co2.csv", text);
  CliResult result = run_cli({"localize", "--log", log});
  INFO(result.out << result.err);
  REQUIRE(result.exit_code == 0);
  CHECK(result.out.find("detection: first reading over the threshold, one detection per 5 m "
                        "(paper 4's ground robot)") != std::string::npos);
  CHECK(result.out.find("reading 10 at (10.00, 0.00): 2500 ppm (threshold 1800)") !=
        std::string::npos);
  result =
      run_cli({"localize", "--log", log, "--moving-average", "5", "--refine-strongest", "--json"});
  REQUIRE(result.exit_code == 0);
  const nlohmann::json detection = nlohmann::json::parse(result.out)["logs"][0]["detection"];
  CHECK(detection["moving_average"] == 5);
  CHECK(detection["refine_strongest"] == true);
  const std::string rule = detection["rule"].get<std::string>();
  CHECK(rule.find("the thesis's future work") != std::string::npos);
  CHECK(rule.find("(not the thesis's ground-robot method)") != std::string::npos);
}
