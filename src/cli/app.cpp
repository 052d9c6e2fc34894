#include "app.hpp"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>

#include "command.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::cli {

void require_option(bool ok, const std::string& option, const std::string& problem,
                    const std::string& expected) {
  if (!ok)
    throw model::InputError(model::Diagnostic{{"(command line)", 0, 0}, option, problem, expected});
}

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"rigdesign: design and verify the sensor rig of an autonomous mobile robot"};
  app.name("rigdesign");
  app.require_subcommand(1);
  app.set_version_flag("--version", "rigdesign 0.1.0");
  const std::vector<Command> commands = {
      setup_metrics(app), setup_check(app),    setup_coverage(app),         setup_select(app),
      setup_filter(app),  setup_simulate(app), setup_occupancy(app),        setup_localize(app),
      setup_costmap(app), setup_export(app),   setup_clearpath_import(app), setup_sensors(app),
      setup_report(app),  setup_serve(app)};

  // CLI11 would say only that the word "was not expected": name it and list the commands.
  if (!args.empty() && !args.front().empty() && args.front().front() != '-') {
    bool known = false;
    std::string names;
    for (const Command& command : commands) {
      known = known || command.app->get_name() == args.front();
      names += (names.empty() ? "" : ", ") + command.app->get_name();
    }
    if (!known) {
      err << "(command line): command: unknown subcommand '" << args.front()
          << "' (expected one of " << names << ")\n";
      return kBadInput;
    }
  }
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 parses from the back
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error, out, err);
    return code == 0 ? kOk : kBadInput;
  }
  try {
    for (const Command& command : commands) {
      if (command.app->parsed()) return command.run(out, err);
    }
  } catch (const model::InputError& error) {
    for (const model::Diagnostic& diagnostic : error.diagnostics())
      err << diagnostic.message() << '\n';
    return kBadInput;
  } catch (const std::filesystem::filesystem_error& error) {
    // Commands check their output folders first (io::prepare_output_folder); this is the
    // backstop for a path that changes under a running command.
    err << (error.path1().empty() ? std::string("(file system)") : error.path1().string()) << ": "
        << error.code().message() << '\n';
    return kBadInput;
  }
  return kBadInput;
}

}  // namespace rigdesign::cli
