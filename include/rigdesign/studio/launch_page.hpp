#pragma once
/// How `serve` opens the browser without putting the token on a command line (issue 53, item
/// 2): every local user reads any process's arguments in /proc/PID/cmdline, so the browser is
/// given the path of a small page, readable by its owner alone, that sends it on to the
/// studio's address with the token.
#include <optional>
#include <string>

namespace rigdesign::studio {

class LaunchPage {
 public:
  /// Writes the page that redirects to `url` into a new private folder (mode 0700, mkdtemp)
  /// under $XDG_RUNTIME_DIR, else $TMPDIR, else /tmp; the file is created new (O_EXCL,
  /// O_NOFOLLOW) with mode 0600. `url` may hold only the characters of an http URL with a
  /// query (letters, digits, and - . _ ~ : / ? = & [ ] %), so it needs no quoting in HTML.
  /// Throws std::runtime_error when the folder or the file cannot be written, and
  /// std::invalid_argument for any other character in `url`.
  explicit LaunchPage(const std::string& url);
  /// Removes the page and its folder.
  ~LaunchPage();
  LaunchPage(const LaunchPage&) = delete;
  LaunchPage& operator=(const LaunchPage&) = delete;

  /// The page's absolute path, to hand to a browser.
  const std::string& path() const { return path_; }

 private:
  std::string folder_;
  std::string path_;
};

/// Starts `program` (looked up on PATH, no shell) with `argument` as its one argument, in the
/// background; a detached thread reaps it. Its process id, or nothing when it did not start.
std::optional<int> start_program(const std::string& program, const std::string& argument);

}  // namespace rigdesign::studio
