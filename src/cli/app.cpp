#include "app.hpp"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <new>
#include <stdexcept>

#include "command.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::cli {

void require_option(bool ok, const std::string& option, const std::string& problem,
                    const std::string& expected) {
  if (!ok)
    throw model::InputError(model::Diagnostic{{"(command line)", 0, 0}, option, problem, expected});
}

std::vector<Command> add_commands(CLI::App& app) {
  app.name("rigdesign");
  app.require_subcommand(1);
  app.set_version_flag("--version", "rigdesign 0.1.0");
  // `rigdesign --help` lists the subcommands by what a user comes to do (issue 51 item 6).
  struct Group {
    const char* name;
    std::vector<Command (*)(CLI::App&)> setups;
  };
  const Group groups[] = {
      {"Design a rig",
       {setup_metrics, setup_check, setup_coverage, setup_select, setup_report, setup_serve,
        setup_sensors}},
      {"Deploy it", {setup_export, setup_clearpath_import}},
      {"Simulate it", {setup_simulate, setup_filter, setup_costmap, setup_occupancy}},
      {"Localise sources", {setup_localize}}};
  std::vector<Command> commands;
  for (const Group& group : groups) {
    for (const auto setup : group.setups) {
      commands.push_back(setup(app));
      commands.back().app->group(group.name);
    }
  }
  return commands;
}

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"rigdesign: design and verify the sensor rig of an autonomous mobile robot"};
  const std::vector<Command> commands = add_commands(app);

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
  } catch (const std::bad_alloc&) {
    err << "rigdesign: out of memory (the inputs ask for more than this machine has)\n";
    return kInternalError;
  } catch (const std::exception& error) {
    // Bad input is an InputError by the time it leaves a module; anything else is a check
    // missing there. Said as such, with no abort, so a CI job reads an exit code.
    err << "rigdesign: internal error: " << error.what()
        << " (an input check is missing: please report this command line)\n";
    return kInternalError;
  }
  return kBadInput;
}

}  // namespace rigdesign::cli
