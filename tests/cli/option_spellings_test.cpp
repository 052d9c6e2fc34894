// Issue 51 item 6: one spelling per concept on the command line. The new spellings do what the
// old ones did, the old ones stay as hidden aliases (not in --help), an old and a new spelling
// of one option together are refused, and --help groups the subcommands by purpose.
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign::test;

namespace {

std::size_t position(const std::string& text, const std::string& word) {
  const std::size_t at = text.find(word);
  INFO(word);
  REQUIRE(at != std::string::npos);
  return at;
}

int files_in(const std::string& folder) {
  int count = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
    count += entry.is_regular_file() ? 1 : 0;
  return count;
}

}  // namespace

TEST_CASE("metrics: --format json is what --json printed, and --help hides --json", "[cli]") {
  const std::string rig = source_path("rigs/cart_two_scanners.yaml");
  const CliResult format = run_cli({"metrics", rig, "--format", "json"});
  const CliResult flag = run_cli({"metrics", rig, "--json"});
  CHECK(format.exit_code == flag.exit_code);
  CHECK(format.out == flag.out);
  REQUIRE_FALSE(format.out.empty());
  CHECK(format.out.front() == '{');
  const CliResult text = run_cli({"metrics", rig, "--format", "text"});
  CHECK(text.out.front() != '{');
  const CliResult help = run_cli({"metrics", "--help"});
  CHECK(help.out.find("--format") != std::string::npos);
  CHECK(help.out.find("--json") == std::string::npos);
}

TEST_CASE("export writes to --out, --to still does, both at once exit 2", "[cli]") {
  const std::string rig = source_path("rigs/cart_two_scanners.yaml");
  TempFolder folder;
  const std::string out = folder.path() + "/out", to = folder.path() + "/to";
  REQUIRE(run_cli({"export", rig, "--out", out}).exit_code == 0);
  REQUIRE(run_cli({"export", rig, "--to", to}).exit_code == 0);
  CHECK(files_in(out) > 0);
  CHECK(files_in(out) == files_in(to));
  const CliResult both = run_cli({"export", rig, "--out", out + "2", "--to", to + "2"});
  CHECK(both.exit_code == 2);
  CHECK_FALSE(std::filesystem::exists(out + "2"));
  const CliResult none = run_cli({"export", rig});
  CHECK(none.exit_code == 2);
  CHECK(none.err.find("--out") != std::string::npos);
}

TEST_CASE("rigdesign --help lists the subcommands by purpose", "[cli]") {
  const CliResult help = run_cli({"--help"});
  const std::size_t design = position(help.out, "Design a rig");
  const std::size_t deploy = position(help.out, "Deploy it");
  const std::size_t simulate = position(help.out, "Simulate it");
  const std::size_t localise = position(help.out, "Localise sources");
  CHECK(design < deploy);
  CHECK(deploy < simulate);
  CHECK(simulate < localise);
  // Each command under its heading (the names as CLI11 prints them, two spaces in).
  for (const char* name : {"  metrics", "  check", "  select", "  serve"}) {
    const std::size_t at = position(help.out, name);
    CHECK((design < at && at < deploy));
  }
  const std::size_t exported = position(help.out, "  export");
  CHECK((deploy < exported && exported < simulate));
  const std::size_t costmap = position(help.out, "  costmap");
  CHECK((simulate < costmap && costmap < localise));
  CHECK(localise < position(help.out, "  localize"));
}
