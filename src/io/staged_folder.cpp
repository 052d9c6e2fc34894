#include "rigdesign/io/staged_folder.hpp"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <vector>

#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/io/output_folder.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {
namespace {

namespace fs = std::filesystem;

constexpr const char* kMarker = ".rigdesign-output";

// The staging folders that exist now, for shown_path().
std::mutex live_mutex;
std::vector<const StagedFolder*> live_folders;
constexpr const char* kPartial = ".partial-";

// Staging folders of runs that no longer exist (killed): their name ends in the dead pid.
void remove_abandoned_staging(const fs::path& parent, const std::string& name) {
  std::error_code error;
  const std::string prefix = "." + name + kPartial;
  for (const auto& entry : fs::directory_iterator(parent, error)) {
    const std::string entry_name = entry.path().filename().string();
    if (entry_name.rfind(prefix, 0) != 0) continue;
    const std::string pid_text = entry_name.substr(prefix.size());
    char* end = nullptr;
    const long pid = std::strtol(pid_text.c_str(), &end, 10);
    if (end == pid_text.c_str() || *end != '\0' || pid <= 0) continue;
    if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) {
      fs::remove_all(entry.path(), error);
    }
  }
}

bool replaceable(const fs::path& folder) {
  std::error_code error;
  return fs::exists(folder / kMarker, error) || fs::is_empty(folder, error);
}

// Moves every file of `from` into `to` (same file system), keeping sub-folders.
void move_files_into(const fs::path& from, const fs::path& to) {
  for (const auto& entry : fs::recursive_directory_iterator(from)) {
    const fs::path target = to / fs::relative(entry.path(), from);
    if (entry.is_directory()) {
      fs::create_directories(target);
    } else {
      fs::rename(entry.path(), target);
    }
  }
}

}  // namespace

std::string shown_path(const std::string& path) {
  const std::lock_guard<std::mutex> lock(live_mutex);
  for (const StagedFolder* folder : live_folders) {
    const std::string& staging = folder->path();
    if (path.rfind(staging, 0) == 0 &&
        (path.size() == staging.size() || path[staging.size()] == '/'))
      return folder->final_name(path);
  }
  return path;
}

StagedFolder::StagedFolder(std::string folder, std::string option)
    : folder_(std::move(folder)), option_(std::move(option)) {
  // Absolute, so "." and "out/" name a folder with a parent to stage beside.
  std::error_code error;
  fs::path final_path = fs::absolute(folder_, error).lexically_normal();
  if (final_path.filename().empty()) final_path = final_path.parent_path();  // "out/"
  if (error || !final_path.has_parent_path() || final_path == final_path.root_path()) {
    throw model::InputError(model::Diagnostic{{"(command line)", 0, 0},
                                              option_,
                                              "'" + folder_ + "' has no parent folder to stage in",
                                              "a folder below the file system's root"});
  }
  const fs::path parent = final_path.has_parent_path() ? final_path.parent_path() : fs::path(".");
  const std::string name = final_path.filename().string();
  fs::create_directories(parent, error);
  if (error) {
    throw model::InputError(
        model::Diagnostic{{"(command line)", 0, 0},
                          option_,
                          "'" + folder_ + "' cannot be created: " + error.message(),
                          "a writable folder"});
  }
  if (fs::exists(final_path, error) && !fs::is_directory(final_path, error)) {
    throw model::InputError(model::Diagnostic{{"(command line)", 0, 0},
                                              option_,
                                              "'" + folder_ + "' is a file, not a folder",
                                              "a folder (new or rigdesign's own)"});
  }
  if (fs::is_symlink(final_path, error) && !fs::is_directory(final_path, error)) {
    throw model::InputError(model::Diagnostic{{"(command line)", 0, 0},
                                              option_,
                                              "'" + folder_ +
                                                  "' is a symbolic link that leads to no folder "
                                                  "(a loop, or a missing target)",
                                              "a folder (new or rigdesign's own)"});
  }
  remove_abandoned_staging(parent, name);
  target_ = final_path.string();
  staging_ = (parent / ("." + name + kPartial + std::to_string(::getpid()))).string();
  fs::remove_all(staging_, error);
  prepare_output_folder(staging_, option_);
  write_file_atomically(staging_ + "/" + kMarker,
                        "Written by rigdesign: the whole folder is replaced on the next run.\n");
  const std::lock_guard<std::mutex> lock(live_mutex);
  live_folders.push_back(this);
}

void StagedFolder::refuse_inputs_inside(const std::vector<std::string>& inputs) const {
  std::error_code error;
  const fs::path folder = fs::weakly_canonical(target_, error);
  if (error) return;  // a folder that cannot be resolved holds no input
  for (const std::string& input : inputs) {
    if (input.empty() || !fs::exists(input, error)) continue;  // nothing there to lose
    const fs::path file = fs::weakly_canonical(input, error);
    if (error) continue;
    const fs::path inside = file.lexically_relative(folder);
    if (inside.empty() || *inside.begin() == "..") continue;
    throw model::InputError(model::Diagnostic{
        {"(command line)", 0, 0},
        option_,
        "'" + folder_ + "' holds the input '" + input +
            "': the folder is replaced by this command's outputs, which would delete it",
        "an output folder that holds none of the command's inputs"});
  }
}

StagedFolder::~StagedFolder() {
  {
    const std::lock_guard<std::mutex> lock(live_mutex);
    live_folders.erase(std::remove(live_folders.begin(), live_folders.end(), this),
                       live_folders.end());
  }
  if (committed_) return;
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
}

std::string StagedFolder::final_name(const std::string& file) const {
  if (file.rfind(staging_, 0) != 0) return file;
  return (fs::path(folder_) / fs::path(file.substr(staging_.size())).relative_path())
      .lexically_normal()
      .string();
}

std::vector<std::string> StagedFolder::final_names(const std::vector<std::string>& files) const {
  std::vector<std::string> names;
  names.reserve(files.size());
  for (const std::string& file : files) names.push_back(final_name(file));
  return names;
}

void StagedFolder::commit() {
  const auto fail = [&](const std::string& problem) {
    throw model::InputError(model::Diagnostic{
        {"(command line)", 0, 0}, option_, "'" + folder_ + "' " + problem, "a writable folder"});
  };
  std::error_code error;
  if (!fs::exists(target_, error)) {
    if (::rename(staging_.c_str(), target_.c_str()) != 0)
      fail(std::string("cannot take the new outputs: ") + std::strerror(errno));
  } else if (replaceable(target_) && !fs::equivalent(target_, fs::current_path(), error)) {
    // (The working folder is filled in place: exchanging it would leave the shell in the old one.)
    // One atomic step: readers see the old folder or the new one (Linux renameat2).
    if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) != 0)
      fail(std::string("cannot take the new outputs: ") + std::strerror(errno));
    fs::remove_all(staging_, error);  // now the previous outputs
  } else {
    fs::remove(fs::path(staging_) / kMarker, error);  // the folder is not rigdesign's alone
    try {
      move_files_into(staging_, target_);
    } catch (const fs::filesystem_error& moving) {
      fail(std::string("cannot take the new outputs: ") + moving.code().message());
    }
    fs::remove_all(staging_, error);
  }
  committed_ = true;
}

}  // namespace rigdesign::io
