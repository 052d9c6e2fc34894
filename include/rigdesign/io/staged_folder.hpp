#pragma once
#include <string>
#include <vector>

namespace rigdesign::io {

/// A command's output folder written as a whole: files go into a hidden sibling
/// (`.NAME.partial-PID`), which replaces the folder in one atomic exchange when the command
/// completes. A reader, or a rerun after `kill -9` or a full disk, finds the previous
/// outputs or the complete new set, never a mix; the previous run's pictures do not linger
/// beside the new ones. A folder rigdesign did not write (no `.rigdesign-output` marker, not
/// empty) is never removed: the new files are moved into it one by one instead.
/// The name a user knows for `path`: its name after commit() when it lies in the staging
/// folder of a StagedFolder that exists, else `path` itself. Error messages use it, so a full
/// disk names `out/report.html`, not `.out.partial-4242/report.html`.
std::string shown_path(const std::string& path);

class StagedFolder {
 public:
  /// Creates the staging folder beside `folder` (and `folder`'s parents), removing staging
  /// folders that killed runs left there. Throws InputError naming `option` when the place
  /// is not writable, before any work is done.
  StagedFolder(std::string folder, std::string option);
  /// Removes the staging folder unless commit() ran: a failed run leaves nothing behind.
  ~StagedFolder();
  StagedFolder(const StagedFolder&) = delete;
  StagedFolder& operator=(const StagedFolder&) = delete;

  /// Throws InputError naming the option when one of `inputs` (files the command reads)
  /// lies inside the folder: replacing the folder would delete what the command reads
  /// (`report DIR/chosen_rig.yaml --out DIR`). Call before any work.
  void refuse_inputs_inside(const std::vector<std::string>& inputs) const;

  /// Where the command writes (the staging folder).
  const std::string& path() const { return staging_; }
  /// The folder the files end up in.
  const std::string& folder() const { return folder_; }
  /// `file` (under path()) as it will be named after commit().
  std::string final_name(const std::string& file) const;
  std::vector<std::string> final_names(const std::vector<std::string>& files) const;
  /// Puts the staged files in place. Throws InputError if the exchange fails (the previous
  /// outputs are then untouched).
  void commit();

 private:
  std::string folder_;
  std::string option_;
  std::string target_;  // folder_ normalised, without a trailing separator
  std::string staging_;
  bool committed_ = false;
};

}  // namespace rigdesign::io
