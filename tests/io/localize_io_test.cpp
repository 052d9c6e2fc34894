#include <catch2/catch.hpp>

#include "rigdesign/io/logs/co2_log_reader.hpp"
#include "rigdesign/io/logs/ground_truth_files.hpp"
#include "rigdesign/io/logs/log_kind.hpp"
#include "rigdesign/io/logs/rssi_csv.hpp"
#include "rigdesign/io/logs/walls_csv.hpp"
#include "rigdesign/localize/co2_log.hpp"
#include "rigdesign/localize/ground_truth.hpp"
#include "rigdesign/localize/rssi_log.hpp"
#include "rigdesign/model/input_error.hpp"
#include "support/input_errors.hpp"

using namespace rigdesign;

namespace {

// The first diagnostic's message of the InputError `parse` throws.
template <typename Parse>
std::string error_of(Parse parse) {
  try {
    parse();
  } catch (const model::InputError& error) {
    return error.diagnostics().front().message();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("an RSSI log parses with its header in any order, comments and blank lines",
          "[localize]") {
  const localize::RssiLog log = io::parse_rssi_csv(
      "# robot "
      "1\nbssid,rssi,t,x,y,z\n\naa:01,-61,0.5,1,2,0.4\r\nbb:02,-70,0.6,1.1,2,0.4\naa:01,-62.5,0.7,"
      "1.2,2,0.4\n",
      "log.csv");
  REQUIRE(log.readings.size() == 3);
  REQUIRE(log.emitters == std::vector<std::string>{"aa:01", "bb:02"});
  CHECK(log.readings[2].emitter == 0);
  CHECK(log.readings[2].rssi_dbm == -62.5);
  CHECK(log.readings[1].position == model::Vec3(1.1, 2, 0.4));
  CHECK(log.readings[0].t == 0.5);
  // The CSV writer's form reads back to the same values.
  const localize::RssiLog again = io::parse_rssi_csv(io::to_rssi_csv(log), "again.csv");
  CHECK(again.readings[1].position == log.readings[1].position);
  CHECK(again.emitters == log.emitters);
}

TEST_CASE("unheard scans (empty rssi) and the receiver's floor and scan period read back",
          "[localize]") {
  const localize::RssiLog log = io::parse_rssi_csv(
      "# floor_dbm: -95\n#scan_period_s:2\nt,x,y,z,bssid,rssi\n0,0,0,0.4,a,-60\n2,0.2,0,0.4,a,\n",
      "log.csv");
  REQUIRE(log.readings.size() == 2);
  CHECK(log.readings[0].heard);
  CHECK_FALSE(log.readings[1].heard);
  REQUIRE(log.floor_dbm);
  CHECK(*log.floor_dbm == -95.0);
  REQUIRE(log.scan_period_s);
  CHECK(*log.scan_period_s == 2.0);
  const localize::RssiLog again = io::parse_rssi_csv(io::to_rssi_csv(log), "again.csv");
  CHECK_FALSE(again.readings[1].heard);
  CHECK(again.floor_dbm == log.floor_dbm);
  CHECK(again.scan_period_s == log.scan_period_s);
}

TEST_CASE("bad RSSI logs name file, line, column and the column's header", "[localize]") {
  CHECK(error_of([] { io::parse_rssi_csv("t,x,y,z,bssid\n0,0,0,0,a\n", "log.csv"); }) ==
        "log.csv:1:1: rssi: column is missing from the header (expected a header line naming the "
        "columns "
        "t,x,y,z,bssid,rssi)");
  // Column 5 is where the third field ("abc") starts on line 3.
  CHECK(error_of([] {
          io::parse_rssi_csv("t,x,y,z,bssid,rssi\n0,0,0,0,a,-50\n1,0,abc,0,a,-50\n", "log.csv");
        }) == "log.csv:3:5: y: 'abc' is not a number (expected a number)");
  CHECK(error_of([] { io::parse_rssi_csv("t,x,y,z,bssid,rssi\n0,0,0,0,a,3\n", "log.csv"); }) ==
        "log.csv:2:11: rssi: is 3 dBm, above 0 dBm (expected a received power in dBm, <= 0, or "
        "empty for a scan that did not hear the emitter)");
  // The receiver's floor comment: line 2, the value starts at column 14.
  CHECK(error_of([] {
          io::parse_rssi_csv("t,x,y,z,bssid,rssi\n# floor_dbm: 5\n0,0,0,0,a,-50\n", "log.csv");
        }).find("log.csv:2:14: floor_dbm: is 5 dBm, above 0 dBm") == 0);
  CHECK(error_of([] {
          io::parse_rssi_csv("# scan_period_s: x\nt,x,y,z,bssid,rssi\n0,0,0,0,a,-50\n", "log.csv");
        }).find("log.csv:1:18: scan_period_s: 'x' is not a number") == 0);
  CHECK(error_of([] {
          io::parse_rssi_csv("t,x,y,z,bssid,rssi\n0,0,0,0,a\n", "log.csv");
        }).find("log.csv:2:10: rssi: is missing") == 0);
  CHECK(error_of([] {
          io::parse_rssi_csv("t,x,y,z,bssid,rssi\n", "log.csv");
        }).find("log.csv:1:1: data: has a header but no readings") == 0);
  CHECK(error_of([] { io::parse_rssi_csv("", "log.csv"); }).find("log.csv: data: is empty") == 0);
  CHECK(error_of([] {
          io::parse_rssi_csv("t,x,y,z,bssid,rssi\n0,0,0,nan,a,-50\n", "log.csv");
        }).find("log.csv:2:7: z: 'nan' is not finite") == 0);
  CHECK(error_of([] {
          io::parse_rssi_csv("t,x,y,z,bssid,rssi\n0,0,0,0,,-50\n", "log.csv");
        }).find("log.csv:2:9: bssid: is empty") == 0);
}

TEST_CASE("CO2 logs: the CSV form and the untimed SubT form", "[localize]") {
  const localize::Co2Log timed =
      io::parse_co2_log("t,x,y,z,co2_ppm\n0,1,2,0.3,450\n1,1.5,2,0.3,460\n", "co2.csv");
  REQUIRE(timed.readings.size() == 2);
  CHECK(timed.timed);
  CHECK(timed.readings[1].ppm == 460);
  const localize::Co2Log untimed =
      io::parse_co2_log("52.70 0.82 499.0\n  52.39\t0.27 498\n", "trace.txt");
  REQUIRE(untimed.readings.size() == 2);
  CHECK_FALSE(untimed.timed);
  CHECK(untimed.readings[1].position == model::Vec3(52.39, 0.27, 0.0));
  CHECK(untimed.readings[1].t == 1.0);  // the reading's index
  CHECK(error_of([] { io::parse_co2_log("1 2 3\n1 2 x\n", "trace.txt"); }) ==
        "trace.txt:2:5: co2_ppm: 'x' is not a number (expected a number)");
  CHECK(error_of([] {
          io::parse_co2_log("1 2 3\n1 2\n", "trace.txt");
        }).find("trace.txt:2:4: co2_ppm: has 2 fields") == 0);
  CHECK(error_of([] {
          io::parse_co2_log("t,x,y,z,co2_ppm\n0,0,0,0,-1\n", "co2.csv");
        }).find("co2.csv:2:9: co2_ppm: is negative") == 0);
  CHECK(error_of([] {
          io::parse_co2_log("t,x,y,co2_ppm\n0,0,0,1\n", "co2.csv");
        }).find("co2.csv:1:1: z: column is missing") == 0);
}

TEST_CASE("a log's kind is told by its first line, ground truth files parse", "[localize]") {
  CHECK(io::log_kind_of("t,x,y,z,bssid,rssi\n", "a") == io::LogKind::rssi);
  CHECK(io::log_kind_of("# c\nt,x,y,z,co2_ppm\n", "a") == io::LogKind::co2);
  CHECK(io::log_kind_of("1 2 400\n", "a") == io::LogKind::co2);
  CHECK(error_of([] {
          io::log_kind_of("t,x,y,z,temperature\n", "a.csv");
        }).find("a.csv:1:1: header:") == 0);
  const auto truth = io::parse_emitter_truth("bssid,x,y,z\naa:01,1,2,3\n", "truth.csv");
  REQUIRE(truth.size() == 1);
  CHECK(truth[0].position == model::Vec3(1, 2, 3));
  CHECK(io::parse_emitter_truth(io::to_emitter_truth_csv(truth), "again.csv")[0].bssid == "aa:01");
}

TEST_CASE("wall maps: losses above 60 dB, far coordinates and over 10000 walls refused (13)",
          "[localize]") {
  const std::string header = "x1,y1,x2,y2,attenuation_db\n";
  CHECK(io::parse_walls_csv(header + "-50,0,50,0,60\n", "w.csv").size() == 1);
  CHECK(test::input_error_of([&] {
          io::parse_walls_csv(header + "-50,0,50,0,1e5\n", "w.csv");
        }).find("w.csv:2:12: attenuation_db: is 100000 dB") == 0);
  CHECK(test::input_error_of([&] {
          io::parse_walls_csv(header + "-50,0,1e9,0,8\n", "w.csv");
        }).find("w.csv:2:7: x2") == 0);
  std::string many = header;
  for (int k = 0; k <= 10000; ++k)
    many += "0," + std::to_string(k) + ",1," + std::to_string(k) + ",3\n";
  CHECK(test::input_error_of([&] {
          io::parse_walls_csv(many, "w.csv");
        }).find("w.csv:10002:1: walls") == 0);
}
