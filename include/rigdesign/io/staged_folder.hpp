#pragma once
#include <string>
#include <vector>

namespace rigdesign::io {

/// The name a user knows for `path`: its name after commit() when it lies in the staging
/// folder of a StagedFolder that exists, else `path` itself. Error messages use it, so a full
/// disk names `out/report.html`, not `.out.partial-4242/report.html`.
std::string shown_path(const std::string& path);

/// A command's output folder: files go into a hidden sibling (`.NAME.partial-PID`), and
/// commit() puts them in place. The folder's `.rigdesign-output` is a manifest: a header
/// line, then the files the last run wrote (paths relative to the folder, one per line).
/// - A new folder, or one holding only the manifest's files (an empty one, an old marker
///   without a list: the whole folder), is exchanged in one atomic step: a reader, or a
///   rerun after `kill -9` or a full disk, finds the previous outputs or the new set.
/// - Otherwise (the working folder, a link to a folder, or files of the user's beside the
///   outputs) the files are moved in one by one: the new set replaces the listed one, listed
///   files the new set lacks are removed, unlisted files are never touched, and a new file
///   whose name an unlisted file holds is refused (InputError, nothing moved). The manifest
///   lists the old and new sets while files move, so after a kill the next run ends with
///   exactly its own set. Links in the folder are never followed to remove a file.
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
  /// Writes the manifest and puts the staged files in place (see above). Throws InputError
  /// naming the option when a new file would overwrite one no run of rigdesign wrote, or
  /// when the exchange fails; the previous outputs are then untouched.
  void commit();

 private:
  std::string folder_;
  std::string option_;
  std::string target_;  // folder_ normalised, without a trailing separator
  std::string staging_;
  bool committed_ = false;
};

}  // namespace rigdesign::io
