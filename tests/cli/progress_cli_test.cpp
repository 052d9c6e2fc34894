// Progress on standard error: RIGDESIGN_PROGRESS=1 asks for it where standard error is no
// terminal (as under ctest); the line counts the command's own units up to the total.
#include <stdlib.h>

#include <catch2/catch.hpp>

#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign::test;

namespace {

// Sets RIGDESIGN_PROGRESS for one scope.
struct ProgressSetting {
  explicit ProgressSetting(const char* value) { ::setenv("RIGDESIGN_PROGRESS", value, 1); }
  ~ProgressSetting() { ::unsetenv("RIGDESIGN_PROGRESS"); }
};

CliResult short_occupancy(const std::string& out) {
  // 0.6 s at 5 Hz: floor(0.6 * 5) = 3 frames.
  return run_cli({"occupancy", "--rig", source_path("rigs/cell.yaml"), "--scene", "cell",
                  "--duration", "0.6", "--rate", "5", "--moving-until", "0.2", "--voxels", "0.2",
                  "--persistence", "paper", "--camera-stride", "4", "--out", out});
}

}  // namespace

TEST_CASE("occupancy reports its frames out of the total on standard error", "[occupancy]") {
  TempFolder folder;
  const ProgressSetting on("1");
  const CliResult result = short_occupancy(folder.path() + "/occ");
  REQUIRE(result.exit_code == 0);
  INFO(result.err);
  CHECK(result.err.find("mapper(s): 3/3 frames (100 %)") != std::string::npos);
  CHECK(result.out.find("frames (") == std::string::npos);  // the report stays clean
}

TEST_CASE("no progress where standard error is no terminal, unless asked", "[occupancy]") {
  TempFolder folder;
  const ProgressSetting off("0");
  const CliResult result = short_occupancy(folder.path() + "/occ");
  REQUIRE(result.exit_code == 0);
  CHECK(result.err.find("frames (") == std::string::npos);
}

TEST_CASE("localize --table counts scenario runs up to scenarios x seeds") {
  const ProgressSetting on("1");
  const CliResult result =
      run_cli({"localize", "--scenario", "corner", "--seeds", "2", "--table", "--method", "wls"});
  REQUIRE(result.exit_code == 0);
  INFO(result.err);
  CHECK(result.err.find("localize: accuracy table: 2/2 runs (100 %)") != std::string::npos);
}
