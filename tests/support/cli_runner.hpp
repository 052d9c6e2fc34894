#pragma once
// Runs the rigdesign command line in-process with an argv, as CLI11's own tests do
// (tests/app_helper.hpp), and keeps its exit code and both output streams.
#include <string>
#include <vector>

namespace rigdesign::test {

struct CliResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

CliResult run_cli(const std::vector<std::string>& args);

/// Absolute path of a file in the source tree.
std::string source_path(const std::string& relative);

}  // namespace rigdesign::test
