#include "rigdesign/io/robot/xacro_environment.hpp"

#include <array>
#include <cstdlib>

namespace rigdesign::io {
namespace {

bool is_identifier(const std::string& name) {
  if (name.empty() || (name[0] >= '0' && name[0] <= '9')) return false;
  for (const char c : name) {
    const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    if (!letter && !(c >= '0' && c <= '9') && c != '_') return false;
  }
  return true;
}

// Variables read by the dynamic loader, the shell, Python, Perl, Ruby, Node or the C
// library when a process starts, and those ROS uses to find code. Prefixes, compared
// upper-cased: `ld_preload` is as dangerous as LD_PRELOAD to a case-insensitive reader.
constexpr std::array kProgramPrefixes = {
    "LD_",         "DYLD_",       "PYTHON",  "PERL",   "RUBY",   "NODE_",    "BASH_",
    "GCONV",       "GLIBC",       "MALLOC",  "ROS_",   "AMENT_", "COLCON_",  "CMAKE_",
    "LC_",         "LOCPATH",     "NLSPATH", "TMPDIR", "SHELL",  "IFS",      "ENV",
    "PS4",         "HOME",        "XDG_",    "GIT_",   "SSL_",   "OPENSSL",  "CURL_",
    "HTTP",        "NO_PROXY",    "ASAN_",   "UBSAN_", "LSAN_",  "TERMINFO", "HOSTALIASES",
    "RES_OPTIONS", "LOCALDOMAIN", "TZ"};

std::string upper(std::string text) {
  for (char& c : text) {
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  }
  return text;
}

}  // namespace

std::optional<std::string> refused_environment_name(const std::string& name) {
  if (!is_identifier(name)) {
    return "is not a variable name (letters, digits and underscores, not starting with a digit)";
  }
  const std::string key = upper(name);
  if (key.find("PATH") != std::string::npos) {
    return "names a search path: a rig file may not change where programs or modules are "
           "found";
  }
  for (const char* prefix : kProgramPrefixes) {
    if (key.rfind(prefix, 0) == 0) {
      return "changes how programs start or find code (" + std::string(prefix) +
             "...): a rig file may not set it";
    }
  }
  return std::nullopt;
}

std::optional<std::string> refused_argument_name(const std::string& name) {
  if (is_identifier(name)) return std::nullopt;
  return "is not a xacro argument name (letters, digits and underscores, not starting with "
         "a digit)";
}

std::vector<std::string> xacro_process_environment(
    const std::map<std::string, std::string>& rig_environment) {
  static constexpr std::array kInherited = {
      "PATH",       "HOME",        "PYTHONPATH",         "AMENT_PREFIX_PATH", "ROS_PACKAGE_PATH",
      "ROS_DISTRO", "ROS_VERSION", "ROS_PYTHON_VERSION", "LD_LIBRARY_PATH",   "LANG",
      "LC_ALL"};
  std::vector<std::string> environment;
  for (const char* name : kInherited) {
    if (const char* value = std::getenv(name))
      environment.push_back(std::string(name) + "=" + value);
  }
  for (const auto& [name, value] : rig_environment) {
    if (!refused_environment_name(name)) environment.push_back(name + "=" + value);
  }
  return environment;
}

}  // namespace rigdesign::io
