#pragma once
// Whole CLI runs in fresh child processes, and the files they leave: for tests that kill a
// run or compare two runs byte for byte (Cairo numbers the glyphs of its SVGs per process,
// so only runs in fresh processes give identical files).
#include <chrono>
#include <map>
#include <string>
#include <vector>

namespace rigdesign::test {

/// Runs the CLI with `args` in a forked child; returns its exit code.
int run_in_child(const std::vector<std::string>& args);

/// Runs the CLI in a forked child and kills it with SIGKILL after `delay` (it may finish
/// first).
void run_and_kill(const std::vector<std::string>& args, std::chrono::microseconds delay);

/// Every regular file under `folder`: path relative to it -> bytes.
using Snapshot = std::map<std::string, std::string>;
Snapshot snapshot(const std::string& folder);

/// Names of the files that differ between two snapshots (for failure messages).
std::string differences(const Snapshot& a, const Snapshot& b);

}  // namespace rigdesign::test
