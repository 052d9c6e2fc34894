// Issue 51 item 4: every numeric option of every subcommand, found by walking the command tree
// (so an option added later is covered without touching this file), driven with NaN,
// infinities, a negative, zero and huge values. A value the option does not mean exits 2 with
// a message naming the option, never an abort or an exception out of the command line; a value
// it does mean (listed below, each with the reason) passes the command line's own checks.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <catch2/catch.hpp>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "command.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

namespace {

// The probes: what a slip of the keyboard, a script's empty variable turned "nan", or a unit
// mix-up (a value in millimetres, a count in bytes) hands an option.
const std::vector<std::string> kProbes = {
    "nan", "inf", "-inf", "-1", "0", "1e300", "9223372036854775808"};

struct NumericOption {
  std::string command;
  std::string name;  // the long name, e.g. "--speed"
  int values = 1;    // how many values it takes at once (--search-area takes 4)
};

bool numeric(const CLI::Option& option) {
  const std::string type = option.get_type_name();
  return type.rfind("FLOAT", 0) == 0 || type.rfind("INT", 0) == 0 || type.rfind("UINT", 0) == 0;
}

std::vector<NumericOption> numeric_options() {
  CLI::App app;
  const std::vector<cli::Command> commands = cli::add_commands(app);
  std::vector<NumericOption> found;
  for (const CLI::App* command : app.get_subcommands({})) {
    for (const CLI::Option* option : command->get_options()) {
      if (!numeric(*option) || option->get_lnames().empty()) continue;
      found.push_back({command->get_name(), "--" + option->get_lnames().front(),
                       std::max(1, option->get_items_expected_min())});
    }
  }
  return found;
}

// Values of the probes an option means, and why. Everything else must be refused.
const std::map<std::string, std::set<std::string>>& meaningful() {
  static const std::map<std::string, std::set<std::string>> table = {
      // Seeds are any 64-bit unsigned number.
      {"costmap --seed", {"0", "9223372036854775808"}},
      {"filter --seed", {"0", "9223372036854775808"}},
      {"localize --seed", {"0", "9223372036854775808"}},
      {"occupancy --seed", {"0", "9223372036854775808"}},
      {"simulate --seed", {"0", "9223372036854775808"}},
      // A global frame may sit below the floor (a map frame at a lower storey) or on it.
      {"check --global-frame-height", {"-1", "0"}},
      {"costmap --global-frame-height", {"-1", "0"}},
      {"export --global-frame-height", {"-1", "0"}},
      // Zero means "none" or "no margin" for these.
      {"costmap --frame-every", {"0"}},
      {"costmap --clearance-margin", {"0"}},
      {"costmap --margins", {"0"}},
      {"export --processing-latency", {"0"}},
      {"filter --threads", {"0"}},  // 0: the pipeline's own thread count
      {"occupancy --moving-until", {"0"}},
      {"occupancy --min-height", {"0"}},
      {"simulate --dropout", {"0"}},  // no ray lost
      {"select --tolerance", {"0"}},  // a rig held exactly at its poses
      {"sensors --min-range", {"0"}},
      {"sensors --min-rate", {"0"}},
      {"sensors --min-fov-deg", {"0"}},
      {"serve --port", {"0"}},  // 0: the system picks a free port
      // Azimuths are signed degrees.
      {"coverage --angles", {"-1", "0"}},
      // Radio levels in dBm and offsets in dB are signed; zeros switch a prior or effect off.
      {"localize --rssi-at-1m", {"-1", "0"}},
      {"localize --cutoff", {"-1", "0"}},
      {"localize --floor", {"-1", "0"}},
      {"localize --tx-offset", {"-1", "0"}},
      {"localize --search-area", {"-1", "0"}},
      {"localize --exponent-prior", {"0"}},
      {"localize --path-prior", {"0"}},
      {"localize --search-margin", {"0"}},
      {"localize --checkpoints", {"0"}},
      {"localize --shadowing", {"0"}},
      {"localize --wall-loss", {"0"}},
      {"localize --time-constant", {"0"}},
  };
  return table;
}

bool is_meaningful(const NumericOption& option, const std::string& value) {
  const auto row = meaningful().find(option.command + " " + option.name);
  return row != meaningful().end() && row->second.count(value) > 0;
}

// A command line each subcommand accepts as it stands, quick to refuse a bad option: small
// bundled rigs, outputs in a temporary folder.
std::vector<std::string> base_command(const std::string& command, const std::string& out) {
  const std::string cart = source_path("rigs/cart_two_scanners.yaml");
  const std::string cell = source_path("rigs/cell.yaml");
  const std::map<std::string, std::vector<std::string>> bases = {
      {"metrics", {"metrics", cart}},
      {"check", {"check", cart}},
      {"coverage", {"coverage", cart, "--out", out}},
      {"select",
       {"select", "--catalog", source_path("rigs/catalogs/ur_cleaner.yaml"), "--requirements",
        source_path("rigs/requirements/ur_cleaner.yaml"), "--budget", "3000", "--out", out}},
      {"filter", {"filter", "--rig", cart, "--scene", "corridor", "--frames", "1"}},
      {"simulate", {"simulate", cart, "--scene", "corridor", "--out", out}},
      {"occupancy", {"occupancy", "--rig", cell, "--duration", "1", "--out", out}},
      {"localize", {"localize", "--scenario", "corner", "--out", out}},
      {"costmap", {"costmap", cart, "--scenario", "wall_following", "--out", out}},
      {"export", {"export", cart, "--to", out}},
      {"sensors", {"sensors"}},
      {"report", {"report", cart, "--out", out}},
      {"serve", {"serve", cart}},
  };
  const auto base = bases.find(command);
  REQUIRE(base != bases.end());
  return base->second;
}

std::vector<std::string> with_option(std::vector<std::string> args, const NumericOption& option,
                                     const std::string& value) {
  args.push_back(option.name);
  for (int i = 0; i < option.values; ++i) args.push_back(value);
  return args;
}

// Whether the command line's own checks (CLI11's conversions and validators) take `args`.
bool parses(const std::vector<std::string>& args) {
  CLI::App app;
  // The commands own the variables their options write: they must outlive the parse.
  const std::vector<cli::Command> commands = cli::add_commands(app);
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError&) {
    return false;
  }
  return true;
}

}  // namespace

TEST_CASE("the command tree has the numeric options this test drives", "[cli]") {
  const std::vector<NumericOption> options = numeric_options();
  // Not a count to keep in step: a floor that fails if the walk stops finding options.
  CHECK(options.size() >= 60);
  const auto has = [&](const std::string& command, const std::string& name) {
    return std::any_of(options.begin(), options.end(), [&](const NumericOption& option) {
      return option.command == command && option.name == name;
    });
  };
  CHECK(has("costmap", "--speed"));
  CHECK(has("localize", "--search-area"));
  CHECK(has("select", "--budget"));
  // Every row of the table names an option the walk finds, so a renamed option is noticed.
  for (const auto& [key, values] : meaningful()) {
    const std::size_t space = key.find(' ');
    INFO(key);
    CHECK(has(key.substr(0, space), key.substr(space + 1)));
  }
}

TEST_CASE("every numeric option refuses what it does not mean with exit 2", "[cli]") {
  TempFolder folder;
  for (const NumericOption& option : numeric_options()) {
    const std::vector<std::string> base = base_command(option.command, folder.path() + "/out");
    for (const std::string& value : kProbes) {
      const std::vector<std::string> args = with_option(base, option, value);
      INFO(option.command << " " << option.name << " " << value);
      if (is_meaningful(option, value)) {
        CHECK(parses(args));
        continue;
      }
      // The studio would start serving if its checks let a value through: never run it.
      if (option.command == "serve") {
        CHECK_FALSE(parses(args));
        continue;
      }
      const CliResult result = run_cli(args);
      CHECK(result.exit_code == 2);
      CHECK(result.err.find(option.name) != std::string::npos);
    }
  }
}
