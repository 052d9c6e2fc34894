#include "package_locator.hpp"

#include <cstdlib>
#include <filesystem>

#include "rigdesign/io/file_bytes.hpp"
#include "rigdesign/model/input_error.hpp"
#include "xml_tree.hpp"

namespace rigdesign::io {
namespace {

namespace fs = std::filesystem;

// How deep below a listed folder packages are looked for (a workspace's src/vendor/pkg).
constexpr int kSearchDepth = 4;

std::vector<std::string> split_paths(const char* value) {
  std::vector<std::string> parts;
  if (!value) return parts;
  std::stringstream stream(value);
  std::string part;
  while (std::getline(stream, part, ':')) {
    if (!part.empty()) parts.push_back(part);
  }
  return parts;
}

}  // namespace

std::optional<std::string> package_name_of(const std::string& package_xml) {
  // A package.xml that is a FIFO or cannot be read names no package (and is never waited on).
  std::string content;
  try {
    content = read_file_bytes(package_xml, "a package.xml");
  } catch (const model::InputError&) {
    return std::nullopt;
  }
  // package.xml formats 1-3 all hold one <name> element directly under <package>.
  const auto open = content.find("<name>");
  const auto close = content.find("</name>", open);
  if (open == std::string::npos || close == std::string::npos) return std::nullopt;
  const std::string name = xml::trimmed(content.substr(open + 6, close - open - 6));
  if (name.empty()) return std::nullopt;
  return name;
}

PackageLocator::PackageLocator(std::vector<std::string> folders) {
  // Absolute, so $(find PKG) gives a path that does not depend on the including file.
  for (const std::string& folder : folders)
    roots_.push_back(fs::absolute(folder).lexically_normal().string());
  for (const std::string& folder : split_paths(std::getenv("ROS_PACKAGE_PATH")))
    roots_.push_back(folder);
  ament_prefixes_ = split_paths(std::getenv("AMENT_PREFIX_PATH"));
}

void PackageLocator::index(const std::string& root) const {
  std::error_code error;
  if (!fs::is_directory(root, error)) return;
  if (const auto name = package_name_of((fs::path(root) / "package.xml").string())) {
    remember(*name, fs::path(root).lexically_normal().string());
    return;  // packages do not nest
  }
  fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, error);
  for (; !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
    if (it.depth() >= kSearchDepth) {
      it.disable_recursion_pending();
      continue;
    }
    if (!it->is_directory(error)) continue;
    const std::string name_of = (it->path() / "package.xml").string();
    if (const auto name = package_name_of(name_of)) {
      remember(*name, it->path().lexically_normal().string());
      it.disable_recursion_pending();
    }
  }
}

void PackageLocator::remember(const std::string& package, const std::string& folder) const {
  const auto [it, added] = found_.emplace(package, folder);
  if (!added && it->second != folder) hidden_[package].push_back(folder);
}

std::vector<PackageLocator::Shadowed> PackageLocator::shadowed() const {
  std::vector<Shadowed> shadowed;
  for (const auto& [package, hidden] : hidden_) {
    if (asked_.count(package)) shadowed.push_back({package, found_.at(package), hidden});
  }
  return shadowed;
}

std::optional<std::string> PackageLocator::find(const std::string& package) const {
  asked_.insert(package);
  if (!indexed_) {
    for (const std::string& root : roots_) index(root);
    indexed_ = true;
  }
  if (const auto it = found_.find(package); it != found_.end()) return it->second;
  for (const std::string& prefix : ament_prefixes_) {
    const fs::path share = fs::path(prefix) / "share" / package;
    std::error_code error;
    if (fs::is_regular_file(share / "package.xml", error)) return share.string();
  }
  return std::nullopt;
}

std::optional<std::string> PackageLocator::resolve_uri(const std::string& uri) const {
  const std::string package_scheme = "package://";
  const std::string file_scheme = "file://";
  if (uri.rfind(file_scheme, 0) == 0) return uri.substr(file_scheme.size());
  if (uri.rfind(package_scheme, 0) != 0) return uri;
  const std::string rest = uri.substr(package_scheme.size());
  const auto slash = rest.find('/');
  const std::string package = rest.substr(0, slash);
  const auto folder = find(package);
  if (!folder) return std::nullopt;
  return slash == std::string::npos ? *folder : *folder + rest.substr(slash);
}

}  // namespace rigdesign::io
