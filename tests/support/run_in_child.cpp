#include "support/run_in_child.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "support/cli_runner.hpp"

namespace rigdesign::test {
namespace {

pid_t start_child(const std::vector<std::string>& args) {
  const pid_t child = ::fork();
  if (child < 0) throw std::runtime_error("fork failed");
  if (child == 0) ::_exit(run_cli(args).exit_code);
  return child;
}

}  // namespace

int run_in_child(const std::vector<std::string>& args) {
  const pid_t child = start_child(args);
  int status = 0;
  ::waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void run_and_kill(const std::vector<std::string>& args, std::chrono::microseconds delay) {
  const pid_t child = start_child(args);
  std::this_thread::sleep_for(delay);
  ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
}

Snapshot snapshot(const std::string& folder) {
  namespace fs = std::filesystem;
  Snapshot files;
  std::error_code error;
  if (!fs::exists(folder, error)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream stream(entry.path(), std::ios::binary);
    std::stringstream bytes;
    bytes << stream.rdbuf();
    files[fs::relative(entry.path(), folder).string()] = bytes.str();
  }
  return files;
}

std::string differences(const Snapshot& a, const Snapshot& b) {
  std::string names;
  for (const auto& [name, bytes] : a) {
    const auto other = b.find(name);
    if (other == b.end() || other->second != bytes) names += name + " ";
  }
  for (const auto& [name, bytes] : b) {
    if (a.count(name) == 0) names += name + " ";
  }
  return names;
}

}  // namespace rigdesign::test
