#pragma once
#include <string>

namespace rigdesign::test {

/// A fresh folder under the system's temporary directory, removed with its contents when
/// the object goes out of scope.
class TempFolder {
 public:
  TempFolder();
  ~TempFolder();
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;

  const std::string& path() const { return path_; }
  /// Writes `contents` to `name` inside the folder and returns the file's path.
  std::string write(const std::string& name, const std::string& contents) const;
  /// Number of entries in the folder.
  int entries() const;

 private:
  std::string path_;
};

/// The whole text of the file at `path` ("" when it cannot be read).
std::string file_text(const std::string& path);

/// 1-based line on which `marker` first appears in `text` (0 if absent).
int line_of(const std::string& text, const std::string& marker);

}  // namespace rigdesign::test
