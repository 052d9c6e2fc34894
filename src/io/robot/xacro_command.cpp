#include "xacro_command.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& path) {
  std::ifstream stream(path, std::ios::binary);
  std::stringstream text;
  text << stream.rdbuf();
  return text.str();
}

}  // namespace

std::optional<std::string> find_xacro_executable() {
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  std::stringstream folders(path);
  for (std::string folder; std::getline(folders, folder, ':');) {
    if (folder.empty()) continue;
    const fs::path candidate = fs::path(folder) / "xacro";
    if (::access(candidate.c_str(), X_OK) == 0 && fs::is_regular_file(candidate)) {
      return candidate.string();
    }
  }
  return std::nullopt;
}

std::string run_xacro(const std::string& executable, const std::string& path,
                      const std::map<std::string, std::string>& args,
                      const std::map<std::string, std::string>& environment,
                      const model::SourceLocation& named_at) {
  // Output and messages go to private temporary files, read back once xacro has exited.
  const fs::path folder =
      fs::temp_directory_path() / ("rigdesign-xacro-" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const fs::path out = folder / "out.urdf";
  const fs::path err = folder / "err.txt";
  std::vector<std::string> words = {executable, path};
  for (const auto& [name, value] : args) words.push_back(name + ":=" + value);
  const pid_t child = ::fork();
  if (child == 0) {
    for (const auto& [name, value] : environment) ::setenv(name.c_str(), value.c_str(), 1);
    if (!std::freopen(out.c_str(), "w", stdout) || !std::freopen(err.c_str(), "w", stderr)) {
      ::_exit(127);
    }
    std::vector<char*> argv;
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    ::execv(executable.c_str(), argv.data());
    ::_exit(127);
  }
  int status = 0;
  if (child < 0 || ::waitpid(child, &status, 0) < 0) status = -1;
  const std::string output = read_all(out);
  std::string messages = read_all(err);
  fs::remove_all(folder);
  if (status != 0) {
    while (!messages.empty() && (messages.back() == '\n' || messages.back() == ' '))
      messages.pop_back();
    throw model::InputError(model::Diagnostic{
        named_at, "robot.description",
        "xacro (" + executable + ") failed on '" + path +
            "': " + (messages.empty() ? "exit status " + std::to_string(status) : messages),
        "a description that `xacro` expands, or robot.expander: builtin"});
  }
  return output;
}

}  // namespace rigdesign::io
