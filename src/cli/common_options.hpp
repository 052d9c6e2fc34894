#pragma once
// The options several subcommands share, declared once with one help text each (issue 51
// item 6), so `--rig`, `--sensors`, `--requirements`, `--out` and `--format` mean one thing on
// every command. Old spellings stay as hidden aliases for one release (docs/cli.md).
#include <cstdint>
#include <string>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace rigdesign::cli {

/// `RIG` or `--rig RIG`: the rig file, required.
CLI::Option* add_rig_option(CLI::App& app, std::string& rig);

/// `--sensors FILE`: the sensor library, overriding the one the rig (or catalog) names.
CLI::Option* add_sensors_option(CLI::App& app, std::string& sensors);

/// `--requirements FILE`: requirements R1-R8, overriding the file the rig names.
CLI::Option* add_requirements_option(CLI::App& app, std::string& requirements);

/// `--out FOLDER`: where the command writes its files; `what` says which, and the default.
/// `old_name` (e.g. "--to"), when given, is kept as a hidden alias.
CLI::Option* add_out_option(CLI::App& app, std::string& out, const std::string& what,
                            const std::string& old_name = "");

/// `--seed S`: a whole number in [0, 2^64); `what` says which random choices it seeds. A
/// negative number is refused (CLI11 would wrap -1 round to 2^64 - 1).
CLI::Option* add_seed_option(CLI::App& app, std::uint64_t& seed, const std::string& what);

/// `--format text|json`: machine-readable output, the one way every command asks for it;
/// `json` is set when json is chosen. The former `--json` flag stays as a hidden alias.
void add_format_option(CLI::App& app, bool& json);

}  // namespace rigdesign::cli
