#pragma once
// The rigdesign command line as a function of its arguments and output streams, so tests
// drive it in-process with an argv and read its exit code and messages.
#include <iosfwd>
#include <string>
#include <vector>

namespace rigdesign::cli {

/// Exit codes for every subcommand (DESIGN.md section 3).
enum ExitCode : int { kOk = 0, kRequirementFails = 1, kBadInput = 2 };

/// `args` excludes the program name.
int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace rigdesign::cli
