#include "support/shared_export.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>

#include "support/cli_runner.hpp"

namespace rigdesign::test {
namespace {

// The test binary's modification time: a rebuild starts a new cache.
std::string build_stamp() {
  struct stat info {};
  if (stat("/proc/self/exe", &info) != 0) return "unknown";
  return std::to_string(info.st_mtim.tv_sec) + "_" + std::to_string(info.st_mtim.tv_nsec);
}

std::string folder_name(const std::string& rig, const std::vector<std::string>& args) {
  std::string name = rig;
  for (const std::string& arg : args) name += "_" + arg;
  for (char& c : name) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                       c == '.' || c == '-';
    if (!plain) c = '_';
  }
  return name;
}

// Holds an exclusive lock on a file for its lifetime.
class FileLock {
 public:
  explicit FileLock(const std::string& path) : fd_(open(path.c_str(), O_CREAT | O_RDWR, 0644)) {
    REQUIRE(fd_ >= 0);
    REQUIRE(flock(fd_, LOCK_EX) == 0);
  }
  ~FileLock() {
    flock(fd_, LOCK_UN);
    close(fd_);
  }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_;
};

}  // namespace

std::string shared_export(const std::string& rig, const std::vector<std::string>& given) {
  namespace fs = std::filesystem;
  // `--layer voxel` and `--ros-distro jazzy` are export's defaults: the same files as without
  // them, one folder.
  std::vector<std::string> args;
  for (std::size_t i = 0; i < given.size(); ++i) {
    const bool default_value =
        i + 1 < given.size() && ((given[i] == "--layer" && given[i + 1] == "voxel") ||
                                 (given[i] == "--ros-distro" && given[i + 1] == "jazzy"));
    if (default_value) {
      ++i;
      continue;
    }
    args.push_back(given[i]);
  }
  const fs::path root = fs::path(RIGDESIGN_TEST_CACHE_DIR) / "shared_exports";
  fs::create_directories(root);
  const FileLock lock((root / "lock").string());
  const fs::path build = root / build_stamp();
  if (!fs::exists(build)) {
    // A new build: the older builds' exports go.
    for (const fs::directory_entry& entry : fs::directory_iterator(root))
      if (entry.is_directory()) fs::remove_all(entry.path());
    fs::create_directories(build);
  }
  const fs::path folder = build / folder_name(rig, args);
  if (!fs::exists(folder)) {
    const fs::path partial = build / (folder.filename().string() + ".partial");
    fs::remove_all(partial);
    std::vector<std::string> command = {"export", source_path(rig), "--to", partial.string()};
    command.insert(command.end(), args.begin(), args.end());
    const CliResult result = run_cli(command);
    INFO(result.err);
    REQUIRE(result.exit_code == 0);
    fs::rename(partial, folder);  // whole or not at all
  }
  return folder.string();
}

}  // namespace rigdesign::test
