#pragma once
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace CLI {
class App;
}
namespace rigdesign::report {
struct FileReport;
}

namespace rigdesign::cli {

/// A registered subcommand: its CLI11 node and what to run once it has been parsed.
struct Command {
  CLI::App* app = nullptr;
  std::function<int(std::ostream& out, std::ostream& err)> run;
};

/// Throws InputError naming the command-line option unless `ok` (exit code 2).
void require_option(bool ok, const std::string& option, const std::string& problem,
                    const std::string& expected);

/// Registers every subcommand on `app` (grouped by purpose for --help) and sets the program's
/// name, version flag and "one subcommand" rule; what `run` parses with, and tests enumerate.
std::vector<Command> add_commands(CLI::App& app);

/// `check`'s exit code for these reports (`check` and `serve`'s save): 2 when any file is
/// invalid, else 1 when any requirement fails, else 0.
int check_exit_code(const std::vector<report::FileReport>& reports);

Command setup_metrics(CLI::App& parent);
Command setup_check(CLI::App& parent);
Command setup_coverage(CLI::App& parent);
Command setup_select(CLI::App& parent);
Command setup_filter(CLI::App& parent);
Command setup_simulate(CLI::App& parent);
Command setup_localize(CLI::App& parent);
Command setup_occupancy(CLI::App& parent);
Command setup_costmap(CLI::App& parent);
Command setup_export(CLI::App& parent);
Command setup_clearpath_import(CLI::App& parent);
Command setup_sensors(CLI::App& parent);
Command setup_report(CLI::App& parent);
Command setup_serve(CLI::App& parent);

}  // namespace rigdesign::cli
