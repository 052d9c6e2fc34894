#include "common_options.hpp"

#include <CLI/CLI.hpp>

#include "rigdesign/io/file_bytes.hpp"

namespace rigdesign::cli {
namespace {

// An option CLI11 accepts but --help does not list.
constexpr const char* kHidden = "";

CLI::Validator not_a_pipe_or_device() {
  // Refused before any command starts: `serve` would otherwise keep waiting to show the load
  // error, and a FIFO's open would wait for a writer. A folder is left to the reader's message.
  return CLI::Validator(
      [](std::string& path) -> std::string {
        const std::optional<std::string> kind = io::not_a_regular_file(path);
        if (!kind || kind->starts_with("is a folder")) return {};
        return "'" + path + "' " + *kind;
      },
      "FILE");
}

}  // namespace

CLI::Option* add_rig_option(CLI::App& app, std::string& rig) {
  return app.add_option("rig,--rig", rig, "Rig file (rigs/*.yaml; positional or --rig)")
      ->required()
      ->check(not_a_pipe_or_device());
}

CLI::Option* add_sensors_option(CLI::App& app, std::string& sensors) {
  return app.add_option("--sensors", sensors,
                        "Sensor library (default: the one the rig or catalog names, else a "
                        "sensors.yaml in its folder or above, else the bundled one)");
}

CLI::Option* add_requirements_option(CLI::App& app, std::string& requirements) {
  return app.add_option("--requirements", requirements,
                        "Application requirements R1-R8 (default: the file the rig names)");
}

CLI::Option* add_out_option(CLI::App& app, std::string& out, const std::string& what,
                            const std::string& old_name) {
  CLI::Option* option = app.add_option("--out", out, "Output folder: " + what);
  if (!old_name.empty()) {
    CLI::Option* alias = app.add_option(old_name, out, "Former name of --out")->group(kHidden);
    option->excludes(alias);
  }
  return option;
}

CLI::Option* add_seed_option(CLI::App& app, std::uint64_t& seed, const std::string& what) {
  const std::string expected = "a whole number from 0 to 18446744073709551615";
  return app.add_option("--seed", seed, "Seed of " + what)
      ->check(CLI::Validator(
          [expected](std::string& text) -> std::string {
            if (text.find('-') == std::string::npos) return {};
            return "is " + text + " (expected " + expected + ")";
          },
          expected));
}

void add_format_option(CLI::App& app, bool& json) {
  app.add_option_function<std::string>(
         "--format", [&json](const std::string& format) { json = format == "json"; },
         "Output format: text (default) or json")
      ->check(CLI::IsMember({"text", "json"}));
  app.add_flag("--json", json, "Former spelling of --format json")->group(kHidden);
}

}  // namespace rigdesign::cli
