#include "rigdesign/io/atomic_write.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "rigdesign/io/staged_folder.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
  throw model::InputError(
      model::Diagnostic{{shown_path(path), 0, 0}, "output", problem, "a writable path"});
}

}  // namespace

void write_file_atomically(const std::string& path, const std::string& contents) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::string temporary = (folder / ("." + target.filename().string() + ".XXXXXX")).string();
  const int descriptor = ::mkstemp(temporary.data());
  if (descriptor < 0)
    fail(path, std::string("cannot create a file beside it: ") + std::strerror(errno));
  // write(2) rather than a stream, so a full disk is reported as such (ENOSPC), not as a
  // bare failure; close(2) is checked too, as some file systems report errors only there.
  const char* next = contents.data();
  std::size_t left = contents.size();
  int failure = 0;
  while (left > 0) {
    const ssize_t written = ::write(descriptor, next, left);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) {
      failure = written < 0 ? errno : EIO;
      break;
    }
    next += written;
    left -= static_cast<std::size_t>(written);
  }
  if (::close(descriptor) != 0 && failure == 0) failure = errno;
  if (failure != 0) {
    ::unlink(temporary.c_str());
    fail(path, std::string("cannot write: ") + std::strerror(failure));
  }
  std::error_code error;
  fs::permissions(temporary,
                  fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                      fs::perms::others_read,
                  error);
  fs::rename(temporary, target, error);
  if (error) {
    std::remove(temporary.c_str());
    fail(path, "cannot rename into place: " + error.message());
  }
}

}  // namespace rigdesign::io
