#include "rigdesign/io/staged_folder.hpp"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>
#include <optional>
#include <set>
#include <vector>

#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/io/output_folder.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {
namespace {

namespace fs = std::filesystem;

constexpr const char* kMarker = ".rigdesign-output";
// The manifest's first line. A marker whose first line differs (written before issue 53)
// lists nothing: the whole folder it marks was rigdesign's.
constexpr const char* kManifestHeader =
    "rigdesign output: the files below were written by its last run and are replaced by the "
    "next; files not listed are not rigdesign's and are never touched";
// write_file_atomically's temporaries of the marker ("..rigdesign-output.XXXXXX": a dot
// before the name), left by a run killed while writing it.
constexpr std::size_t kMarkerTemporaryLength = 6;

// The staging folders that exist now, for shown_path().
std::mutex live_mutex;
std::vector<const StagedFolder*> live_folders;
constexpr const char* kPartial = ".partial-";

// Paths relative to an output folder, '/'-separated, sorted (so a manifest is the same bytes
// for the same set).
using Names = std::set<std::string>;

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

bool is_marker_temporary(const std::string& name) {
  const std::string prefix = "." + std::string(kMarker) + ".";
  if (name.size() != prefix.size() + kMarkerTemporaryLength || name.rfind(prefix, 0) != 0)
    return false;
  return std::all_of(name.begin() + static_cast<std::ptrdiff_t>(prefix.size()), name.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; });
}

// What a folder holds, without following symbolic links: the marker and its temporaries
// are not counted.
struct FolderContents {
  Names files;           // every entry that is not a folder (regular files, links, pipes, ...)
  Names folders;         // every real folder below the top
  bool complete = true;  // false when part of it could not be read
};

FolderContents contents_of(const fs::path& folder) {
  FolderContents contents;
  std::error_code error;
  fs::recursive_directory_iterator it(folder, error), end;
  if (error) contents.complete = false;
  for (; !error && it != end; it.increment(error)) {
    const std::string name = it->path().lexically_relative(folder).generic_string();
    if (it.depth() == 0 && (name == kMarker || is_marker_temporary(name))) continue;
    const fs::file_status status = it->symlink_status(error);
    if (error) break;
    if (fs::is_directory(status)) {
      contents.folders.insert(name);
    } else {
      contents.files.insert(name);
    }
  }
  if (error) contents.complete = false;
  return contents;
}

// A manifest line names a file below the folder: relative, no "." or ".." step, no empty
// step. Other lines (a hand-edited or hostile manifest) name nothing rigdesign may touch.
bool plain_relative(const std::string& name) {
  if (name.empty() || name.front() == '/' || name.find('\0') != std::string::npos) return false;
  std::size_t start = 0;
  while (start <= name.size()) {
    const std::size_t slash = std::min(name.find('/', start), name.size());
    const std::string step = name.substr(start, slash - start);
    if (step.empty() || step == "." || step == "..") return false;
    start = slash + 1;
  }
  return true;
}

// The folder's marker: absent, a list of files (a manifest), or an old marker without one.
struct Marker {
  bool present = false;
  bool lists = false;  // false with `present`: the whole folder is rigdesign's
  Names files;
};

Marker read_marker(const fs::path& folder) {
  Marker marker;
  std::error_code error;
  // Not followed, and never a pipe to block on: only a regular file is a marker.
  if (!fs::is_regular_file(fs::symlink_status(folder / kMarker, error))) return marker;
  std::ifstream stream(folder / kMarker, std::ios::binary);
  std::string line;
  if (!stream || !std::getline(stream, line)) return marker;
  marker.present = true;
  if (line != kManifestHeader) return marker;
  marker.lists = true;
  while (std::getline(stream, line)) {
    if (plain_relative(line)) marker.files.insert(line);
  }
  return marker;
}

std::string manifest_text(const Names& files) {
  std::string text = std::string(kManifestHeader) + "\n";
  for (const std::string& file : files) text += file + "\n";
  return text;
}

// The folders `name` lies in, outermost first ("a/b/c.txt": "a", "a/b").
std::vector<std::string> folders_above(const std::string& name) {
  std::vector<std::string> folders;
  for (std::size_t slash = name.find('/'); slash != std::string::npos;
       slash = name.find('/', slash + 1))
    folders.push_back(name.substr(0, slash));
  return folders;
}

// Whether every folder `name` lies in is a real folder below `top` (none is a symbolic link
// that could lead out of it).
bool in_real_folders(const fs::path& top, const std::string& name) {
  std::error_code error;
  for (const std::string& folder : folders_above(name)) {
    const fs::file_status status = fs::symlink_status(top / folder, error);
    if (error || !fs::is_directory(status)) return false;
  }
  return true;
}

// The first path of `written` the folder holds as something rigdesign may not replace: a
// file no manifest lists, a folder where a file goes, or a file or link where a folder goes.
std::optional<std::string> first_clash(const fs::path& top, const Names& written,
                                       const Names& owned) {
  std::error_code error;
  for (const std::string& name : written) {
    for (const std::string& folder : folders_above(name)) {
      const fs::file_status status = fs::symlink_status(top / folder, error);
      // A file an earlier run wrote may give way to a folder; a link or a user's file not.
      const bool replaceable_file = fs::is_regular_file(status) && owned.count(folder) != 0;
      if (fs::exists(status) && !fs::is_directory(status) && !replaceable_file) return folder;
    }
    const fs::file_status status = fs::symlink_status(top / name, error);
    if (!fs::exists(status)) continue;
    if (fs::is_directory(status) || owned.count(name) == 0) return name;
  }
  return std::nullopt;
}

// Whether the folder holds nothing but what `owned` lists and the folders they lie in: then
// it may be exchanged whole.
bool holds_only(const FolderContents& contents, const Names& owned) {
  if (!contents.complete) return false;
  Names needed_folders;
  for (const std::string& name : owned) {
    for (const std::string& folder : folders_above(name)) needed_folders.insert(folder);
  }
  return std::includes(owned.begin(), owned.end(), contents.files.begin(), contents.files.end()) &&
         std::includes(needed_folders.begin(), needed_folders.end(), contents.folders.begin(),
                       contents.folders.end());
}

// Whether the working folder is `folder` or lies in it: exchanging it would leave the shell
// in the old folder, which is then removed.
bool holds_working_folder(const fs::path& folder) {
  std::error_code error;
  const fs::path here = fs::weakly_canonical(fs::current_path(error), error);
  const fs::path there = fs::weakly_canonical(folder, error);
  if (error) return true;  // unknown: do not exchange
  const fs::path inside = here.lexically_relative(there);
  return !inside.empty() && *inside.begin() != "..";
}

// Moves the staged files into `top` one by one and removes the `stale` ones. The manifest
// first lists the old and new sets together and last the new set alone, so a run killed
// between two moves leaves every file rigdesign wrote listed: the next run replaces or
// removes them all. Throws fs::filesystem_error.
void fill_in_place(const fs::path& staging, const fs::path& top, const Names& written,
                   const Names& stale) {
  Names listed_while_moving = stale;
  listed_while_moving.insert(written.begin(), written.end());
  write_file_atomically((top / kMarker).string(), manifest_text(listed_while_moving));
  for (const std::string& name : written) {
    for (const std::string& folder : folders_above(name)) {
      // first_clash() let only a file an earlier run wrote stand in the way of a folder.
      std::error_code error;
      if (fs::is_regular_file(fs::symlink_status(top / folder, error))) fs::remove(top / folder);
      fs::create_directory(top / folder, error);
      if (error) throw fs::filesystem_error("create folder", top / folder, error);
    }
    fs::rename(staging / name, top / name);
  }
  Names emptied;  // folders that held a removed file, deepest first when walked in reverse
  for (const std::string& name : stale) {
    std::error_code error;
    // Never through a link: the manifest may name "a/f" where "a" now leads out of the folder.
    if (!in_real_folders(top, name)) continue;
    const fs::file_status status = fs::symlink_status(top / name, error);
    if (!fs::exists(status) || fs::is_directory(status)) continue;  // gone, or not a file now
    fs::remove(top / name, error);
    for (const std::string& folder : folders_above(name)) emptied.insert(folder);
  }
  for (auto folder = emptied.rbegin(); folder != emptied.rend(); ++folder)
    ::rmdir((top / *folder).c_str());  // only if empty: a user's file keeps its folder
  write_file_atomically((top / kMarker).string(), manifest_text(written));
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(top, error)) {
    if (is_marker_temporary(entry.path().filename().string())) fs::remove(entry.path(), error);
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
  prepare_output_folder(staging_, option_);  // the manifest is written by commit()
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
  const FolderContents staged = contents_of(staging_);
  if (!staged.complete) fail("cannot list the new outputs");
  const Names& written = staged.files;
  for (const std::string& name : written) {
    if (name.find_first_of("\n\r") != std::string::npos)
      fail("cannot list the output '" + name + "' in its manifest (a line break in its name)");
  }
  write_file_atomically(staging_ + "/" + kMarker, manifest_text(written));
  std::error_code error;
  if (!fs::exists(fs::symlink_status(target_, error))) {
    if (::rename(staging_.c_str(), target_.c_str()) != 0)
      fail(std::string("cannot take the new outputs: ") + std::strerror(errno));
    committed_ = true;
    return;
  }
  const fs::path top(target_);
  const Marker previous = read_marker(top);
  const FolderContents present = contents_of(top);
  // An old marker without a list: every file there was rigdesign's.
  const Names owned = previous.lists ? previous.files : previous.present ? present.files : Names{};
  // Whole when the folder holds only what rigdesign wrote, and is not the working folder or
  // a link to a folder (exchanging would replace the link itself).
  const bool whole = ((previous.present && !previous.lists) || holds_only(present, owned)) &&
                     !fs::is_symlink(fs::symlink_status(top, error)) && !holds_working_folder(top);
  if (whole) {
    // One atomic step: readers see the old folder or the new one (Linux renameat2).
    if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) != 0)
      fail(std::string("cannot take the new outputs: ") + std::strerror(errno));
    fs::remove_all(staging_, error);  // now the previous outputs
    committed_ = true;
    return;
  }
  if (const std::optional<std::string> clash = first_clash(top, written, owned)) {
    // Nothing is touched; the destructor removes the staging folder.
    throw model::InputError(model::Diagnostic{
        {"(command line)", 0, 0},
        option_,
        "'" + folder_ + "' holds '" + *clash +
            "', which no rigdesign run wrote (it is not listed in the folder's " + kMarker +
            "): the new outputs would overwrite it",
        "a new folder, or one whose files of the same names rigdesign wrote: move '" + *clash +
            "' away or choose another " + option_});
  }
  // File by file, leaving what no run listed. A file of an old marker without a list is
  // replaced by one of the same name, but no other is removed (this folder is the working
  // folder, or a link to one: never emptied on an old marker's word).
  Names stale;
  if (previous.lists)
    std::set_difference(owned.begin(), owned.end(), written.begin(), written.end(),
                        std::inserter(stale, stale.end()));
  try {
    fill_in_place(staging_, top, written, stale);
  } catch (const fs::filesystem_error& moving) {
    fail(std::string("cannot take the new outputs: ") + moving.code().message());
  }
  fs::remove_all(staging_, error);
  committed_ = true;
}

}  // namespace rigdesign::io
