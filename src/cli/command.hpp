#pragma once
#include <functional>
#include <iosfwd>

namespace CLI {
class App;
}

namespace rigdesign::cli {

/// A registered subcommand: its CLI11 node and what to run once it has been parsed.
struct Command {
  CLI::App* app = nullptr;
  std::function<int(std::ostream& out, std::ostream& err)> run;
};

Command setup_metrics(CLI::App& parent);
Command setup_check(CLI::App& parent);
Command setup_coverage(CLI::App& parent);
Command setup_select(CLI::App& parent);

}  // namespace rigdesign::cli
