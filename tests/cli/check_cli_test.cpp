#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/cli_runner.hpp"
#include "support/fixture_files.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign::test;

namespace {

std::string read_file(const std::string& path) {
  std::ifstream stream(path);
  std::stringstream contents;
  contents << stream.rdbuf();
  return contents.str();
}

// A folder with the valid fixture, the rig's requirements replaced by `requirements`.
struct CheckFolder {
  TempFolder folder;
  std::string rig;
  explicit CheckFolder(const std::string& requirements = kRequirements) {
    folder.write("sensors.yaml", kLibrary);
    folder.write("req.yaml", requirements);
    rig = folder.write("rig.yaml", kRig);
  }
};

std::string with(const std::string& from, const std::string& to) {
  std::string text = kRequirements;
  text.replace(text.find(from), from.size(), to);
  return text;
}

}  // namespace

TEST_CASE("check exits 1 when a requirement fails and names the binding requirement") {
  // 2 m/s with 10 cm between frames needs 20 Hz; the spinner runs at 10 Hz.
  CheckFolder files(with("max_speed: 1.0", "max_speed: 2.0"));
  const CliResult result = run_cli({"check", files.rig});
  CHECK(result.exit_code == 1);
  CHECK(result.out.find("robot_speed: fail: R5 robot speed: F = 10 Hz") != std::string::npos);
  CHECK(result.out.find("[set by top]") != std::string::npos);
}

TEST_CASE("check --requirements overrides the file the rig names") {
  CheckFolder files;
  const std::string strict = files.folder.write("strict.yaml", with("size: 0.15", "size: 0.05"));
  CHECK(run_cli({"check", files.rig}).exit_code == 0);
  const CliResult result = run_cli({"check", files.rig, "--requirements", strict});
  CHECK(result.exit_code == 1);
  CHECK(result.out.find("R6 smallest obstacle") != std::string::npos);
}

TEST_CASE("check reports invalid input over failing requirements (exit 2)") {
  CheckFolder files(with("max_speed: 1.0", "max_speed: 2.0"));
  const std::string broken = files.folder.write("broken.yaml", "name: [\n");
  CHECK(run_cli({"check", files.rig, broken}).exit_code == 2);
}

TEST_CASE("check --format json lists each file's status and findings") {
  CheckFolder files(with("max_speed: 1.0", "max_speed: 2.0"));
  const std::string broken = files.folder.write("broken.yaml", kRig + "extra_field: 1\n");
  const CliResult result = run_cli({"check", files.rig, broken, "--format", "json"});
  const auto report = nlohmann::json::parse(result.out);
  CHECK(report["exit_code"] == 2);
  REQUIRE(report["files"].size() == 2);
  CHECK(report["files"][0]["status"] == "fail");
  CHECK(report["files"][1]["status"] == "invalid");
  const auto& diagnostic = report["files"][1]["diagnostics"][0];
  CHECK(diagnostic["field"] == "extra_field");
  CHECK(diagnostic["line"] == line_of(kRig + "extra_field: 1\n", "extra_field"));
}

TEST_CASE("check --format junit writes XML that an independent parser reads") {
  CheckFolder files(with("max_speed: 1.0", "max_speed: 2.0"));
  const std::string broken = files.folder.write("broken.yaml", "name: <&>\nmounts: 3\n");
  const std::string report = files.folder.path() + "/report.xml";
  const CliResult result =
      run_cli({"check", files.rig, broken, "--format", "junit", "--output", report});
  CHECK(result.exit_code == 2);
  CHECK(result.out.empty());
  // Python's ElementTree parses the file and recounts failures and errors from the elements.
  const std::string script =
      files.folder.write("count.py", R"(import sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
assert root.tag == "testsuites", root.tag
cases = root.findall("./testsuite/testcase")
failures = len(root.findall("./testsuite/testcase/failure"))
errors = len(root.findall("./testsuite/testcase/error"))
assert int(root.get("tests")) == len(cases)
assert int(root.get("failures")) == failures == 1, failures
assert int(root.get("errors")) == errors == 1, errors
for suite in root.findall("testsuite"):
    assert int(suite.get("tests")) == len(suite.findall("testcase"))
)");
  CHECK(std::system(("python3 " + script + " " + report).c_str()) == 0);
}

TEST_CASE("check --output into a missing folder fails cleanly and writes nothing") {
  CheckFolder files;
  const int before = files.folder.entries();
  const CliResult result =
      run_cli({"check", files.rig, "--output", files.folder.path() + "/no/such/dir/report.txt"});
  CHECK(result.exit_code == 2);
  CHECK(result.err.find("output") != std::string::npos);
  CHECK(files.folder.entries() == before);
}

TEST_CASE("check --output replaces the file whole") {
  CheckFolder files;
  const std::string report = files.folder.path() + "/report.txt";
  std::ofstream(report) << "stale content that is longer than nothing\n";
  CHECK(run_cli({"check", files.rig, "--output", report}).exit_code == 0);
  const std::string written = read_file(report);
  CHECK(written.find("stale") == std::string::npos);
  CHECK(written.find("requirements: 7 pass, 0 fail, 0 not evaluated") != std::string::npos);
}
