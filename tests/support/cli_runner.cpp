#include "support/cli_runner.hpp"

#include <sstream>

#include "app.hpp"

namespace rigdesign::test {

CliResult run_cli(const std::vector<std::string>& args) {
  std::ostringstream out;
  std::ostringstream err;
  const int code = cli::run(args, out, err);
  return {code, out.str(), err.str()};
}

std::string source_path(const std::string& relative) {
  return std::string(RIGDESIGN_SOURCE_DIR) + "/" + relative;
}

}  // namespace rigdesign::test
