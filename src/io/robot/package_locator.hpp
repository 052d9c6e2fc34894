#pragma once
/// Where ROS packages live, as `$(find PKG)` and `package://PKG/...` expect: a folder is
/// package PKG when its package.xml names it. Searched, in order: the folders the rig lists
/// (`package_paths`), then ROS_PACKAGE_PATH (ROS 1), then AMENT_PREFIX_PATH's
/// `share/PKG` (ROS 2). Each listed folder may be a package itself or hold packages up to
/// a few levels below it, as a colcon workspace's `src/` does.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace rigdesign::io {

class PackageLocator {
 public:
  /// `folders`: the rig's package_paths, already made absolute. Environment variables are
  /// read once, here.
  explicit PackageLocator(std::vector<std::string> folders);

  /// The package's folder, or nothing when no searched folder holds it.
  std::optional<std::string> find(const std::string& package) const;

  /// Replaces a leading `package://PKG/` by PKG's folder; `file://` is stripped; other
  /// paths are returned unchanged. Nothing when PKG is not found.
  std::optional<std::string> resolve_uri(const std::string& uri) const;

  /// The folders searched, for "not found" messages.
  const std::vector<std::string>& searched() const { return roots_; }

  /// A package asked for that more than one searched folder holds: the one used (the first
  /// found, package_paths before ROS_PACKAGE_PATH) and the ones it hides.
  struct Shadowed {
    std::string package;
    std::string used;
    std::vector<std::string> hidden;
  };
  std::vector<Shadowed> shadowed() const;

 private:
  void index(const std::string& root) const;  // adds root's packages to found_
  void remember(const std::string& package, const std::string& folder) const;
  std::vector<std::string> roots_;
  std::vector<std::string> ament_prefixes_;
  mutable std::map<std::string, std::string> found_;                // package -> folder
  mutable std::map<std::string, std::vector<std::string>> hidden_;  // package -> other folders
  mutable std::set<std::string> asked_;
  mutable bool indexed_ = false;  // the listed folders are scanned at the first find()
};

/// The package name a package.xml declares (its <name>), or nothing.
std::optional<std::string> package_name_of(const std::string& package_xml);

}  // namespace rigdesign::io
