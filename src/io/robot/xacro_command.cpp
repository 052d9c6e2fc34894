#include "xacro_command.hpp"

#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <thread>
#include <vector>

#include "rigdesign/io/robot/xacro_environment.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {
namespace {

namespace fs = std::filesystem;

// ROS's xacro expands real descriptions in about a second; one that runs for minutes is a
// description that multiplies without end (real xacro has no size limit of its own).
constexpr auto kXacroTimeLimit = std::chrono::seconds(120);
// The same bound as the built-in expander's total text.
constexpr off_t kMaxOutputBytes = off_t{64} << 20;

[[noreturn]] void xacro_failed(const model::SourceLocation& named_at, const std::string& problem) {
  throw model::InputError(
      model::Diagnostic{named_at, "robot.description", problem,
                        "a description that `xacro` expands, or robot.expander: builtin"});
}

// A private folder (mkdtemp: a fresh name, mode 0700) removed when the run ends, so no
// planted file or symlink can receive xacro's output.
class PrivateFolder {
 public:
  explicit PrivateFolder(const model::SourceLocation& named_at) {
    std::string pattern = (fs::temp_directory_path() / "rigdesign-xacro-XXXXXX").string();
    if (!::mkdtemp(pattern.data()))
      xacro_failed(named_at, "no temporary folder could be made for xacro");
    path_ = pattern;
  }
  ~PrivateFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  PrivateFolder(const PrivateFolder&) = delete;
  PrivateFolder& operator=(const PrivateFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// A file created new (O_EXCL), never through a symlink (O_NOFOLLOW), readable by us only;
// closed when the run ends.
class PrivateFile {
 public:
  PrivateFile(const fs::path& path, const model::SourceLocation& named_at)
      : fd_(::open(path.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC,
                   S_IRUSR | S_IWUSR)) {
    if (fd_ < 0)
      xacro_failed(named_at, "the temporary file '" + path.string() + "' could not be created");
  }
  ~PrivateFile() { ::close(fd_); }
  PrivateFile(const PrivateFile&) = delete;
  PrivateFile& operator=(const PrivateFile&) = delete;
  int fd() const { return fd_; }

 private:
  int fd_;
};

std::string read_all(int fd, const std::string& what, const model::SourceLocation& named_at) {
  struct stat status {};
  if (::fstat(fd, &status) != 0) xacro_failed(named_at, "xacro's " + what + " could not be read");
  if (status.st_size > kMaxOutputBytes) {
    xacro_failed(named_at,
                 "xacro's " + what + " is larger than 64 MiB (a description that multiplies?)");
  }
  std::string text(static_cast<std::size_t>(status.st_size), '\0');
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t got =
        ::pread(fd, text.data() + done, text.size() - done, static_cast<off_t>(done));
    if (got <= 0) break;
    done += static_cast<std::size_t>(got);
  }
  text.resize(done);
  return text;
}

// Waits for the child, killing it past kXacroTimeLimit; returns its wait status, or -1.
int wait_bounded(pid_t child) {
  const auto deadline = std::chrono::steady_clock::now() + kXacroTimeLimit;
  int status = 0;
  while (true) {
    const pid_t done = ::waitpid(child, &status, WNOHANG);
    if (done == child) return status;
    if (done < 0) return -1;
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(child, SIGKILL);
      ::waitpid(child, &status, 0);
      return -2;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
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
  for (const auto& [name, value] : args) {
    if (const auto why = refused_argument_name(name))
      xacro_failed(named_at, "argument '" + name + "' " + *why);
  }
  const PrivateFolder folder(named_at);
  const PrivateFile out(folder.path() / "out.urdf", named_at);
  const PrivateFile err(folder.path() / "err.txt", named_at);
  // Everything the child needs is built before fork: only async-signal-safe calls after it.
  std::vector<std::string> words = {executable, path};
  for (const auto& [name, value] : args) words.push_back(name + ":=" + value);
  std::vector<std::string> variables = xacro_process_environment(environment);
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  std::vector<char*> envp;
  for (std::string& variable : variables) envp.push_back(variable.data());
  envp.push_back(nullptr);
  const pid_t child = ::fork();
  if (child == 0) {
    const int null_input = ::open("/dev/null", O_RDONLY);
    if (null_input < 0 || ::dup2(null_input, 0) < 0 || ::dup2(out.fd(), 1) < 0 ||
        ::dup2(err.fd(), 2) < 0) {
      ::_exit(127);
    }
    ::execve(executable.c_str(), argv.data(), envp.data());
    ::_exit(127);
  }
  const int status = child < 0 ? -1 : wait_bounded(child);
  const std::string output = read_all(out.fd(), "output", named_at);
  std::string messages = read_all(err.fd(), "messages", named_at);
  if (status == -2) {
    xacro_failed(named_at, "xacro (" + executable + ") ran longer than " +
                               std::to_string(kXacroTimeLimit.count()) + " s on '" + path +
                               "' and was stopped (a description that multiplies?)");
  }
  if (status != 0) {
    while (!messages.empty() && (messages.back() == '\n' || messages.back() == ' '))
      messages.pop_back();
    xacro_failed(named_at,
                 "xacro (" + executable + ") failed on '" + path + "': " +
                     (messages.empty() ? "exit status " + std::to_string(status) : messages));
  }
  return output;
}

}  // namespace rigdesign::io
