#pragma once
// The rigdesign command line as a function of its arguments and output streams, so tests
// drive it in-process with an argv and read its exit code and messages.
#include <iosfwd>
#include <string>
#include <vector>

namespace rigdesign::cli {

/// Exit codes for every subcommand (DESIGN.md section 3). kInternalError: an exception other
/// than bad input left a module (a missing check, or memory ran out), reported, not aborted.
enum ExitCode : int { kOk = 0, kRequirementFails = 1, kBadInput = 2, kInternalError = 3 };

/// `args` excludes the program name.
int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace rigdesign::cli
