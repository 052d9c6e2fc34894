#pragma once
// Puts a folder first on PATH (a stand-in executable, e.g. ROS's xacro) and restores PATH
// however the test ends.
#include <cstdlib>
#include <string>

namespace rigdesign::test {

class PathGuard {
 public:
  explicit PathGuard(const std::string& first)
      : saved_(std::getenv("PATH") ? std::getenv("PATH") : "") {
    ::setenv("PATH", (first + ":" + saved_).c_str(), 1);
  }
  ~PathGuard() { ::setenv("PATH", saved_.c_str(), 1); }
  PathGuard(const PathGuard&) = delete;
  PathGuard& operator=(const PathGuard&) = delete;

 private:
  std::string saved_;
};

}  // namespace rigdesign::test
