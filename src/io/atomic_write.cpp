#include "rigdesign/io/atomic_write.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/xattr.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>

#include "rigdesign/io/staged_folder.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
  throw model::InputError(
      model::Diagnostic{{shown_path(path), 0, 0}, "output", problem, "a writable path"});
}

// write(2) rather than a stream, so a full disk is reported as such (ENOSPC), not as a bare
// failure. Returns 0 or the error number.
int write_all(int descriptor, const std::string& contents) {
  const char* next = contents.data();
  std::size_t left = contents.size();
  while (left > 0) {
    const ssize_t written = ::write(descriptor, next, left);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return written < 0 ? errno : EIO;
    next += written;
    left -= static_cast<std::size_t>(written);
  }
  return 0;
}

// A private temporary beside `path` holding `contents`, synced; its descriptor stays open.
struct Temporary {
  std::string path;
  int descriptor = -1;
};

Temporary temporary_beside(const std::string& path, const std::string& contents) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  Temporary made{(folder / ("." + target.filename().string() + ".XXXXXX")).string(), -1};
  made.descriptor = ::mkstemp(made.path.data());  // mode 0600: the text stays private
  if (made.descriptor < 0)
    fail(path, std::string("cannot create a file beside it: ") + std::strerror(errno));
  int failure = write_all(made.descriptor, contents);
  if (failure == 0 && ::fsync(made.descriptor) != 0) failure = errno;
  if (failure != 0) {
    ::close(made.descriptor);
    ::unlink(made.path.c_str());
    fail(path, std::string("cannot write: ") + std::strerror(failure));
  }
  return made;
}

// Gives the temporary the file's owner, group and mode; false when the owner or group cannot be
// set (we are not root and the file is another's, or its group is not one of ours).
bool take_identity(int descriptor, const struct stat& file) {
  struct stat made {};
  if (::fstat(descriptor, &made) != 0) return false;
  if ((made.st_uid != file.st_uid || made.st_gid != file.st_gid) &&
      ::fchown(descriptor, file.st_uid, file.st_gid) != 0)
    return false;
  // After fchown: a change of owner clears the set-user-ID and set-group-ID bits.
  return ::fchmod(descriptor, file.st_mode & 07777) == 0;
}

void sync_folder(const std::string& path) {
  const std::filesystem::path target(path);
  const std::string folder = target.has_parent_path() ? target.parent_path().string() : ".";
  const int descriptor = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (descriptor < 0) return;  // the rename stands; only its durability is not forced
  ::fsync(descriptor);
  ::close(descriptor);
}

// The whole text from an open descriptor's start; nullopt when it cannot be read.
std::optional<std::string> read_all(int descriptor) {
  std::string text;
  char buffer[65536];
  for (off_t at = 0;;) {
    const ssize_t got = ::pread(descriptor, buffer, sizeof buffer, at);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) return std::nullopt;
    if (got == 0) return text;
    text.append(buffer, static_cast<std::size_t>(got));
    at += got;
  }
}

// `contents` over the open file from its start, cut to its length and synced; 0 or errno.
int overwrite(int descriptor, const std::string& contents) {
  if (::lseek(descriptor, 0, SEEK_SET) != 0) return errno;
  if (const int failure = write_all(descriptor, contents); failure != 0) return failure;
  if (::ftruncate(descriptor, static_cast<off_t>(contents.size())) != 0) return errno;
  return ::fsync(descriptor) == 0 ? 0 : errno;
}

// Writes `contents` into the file itself (every hard link sees it; owner, group, mode and
// attributes untouched). `temporary` already holds the new text, synced: it is removed once
// the file holds it, and kept (and named) only when the file may be left incomplete.
void write_in_place(const std::string& path, const struct stat& file, const std::string& contents,
                    const std::string& temporary) {
  const int descriptor = ::open(path.c_str(), O_RDWR | O_NOFOLLOW | O_CLOEXEC);
  struct stat opened {};
  if (descriptor < 0 || ::fstat(descriptor, &opened) != 0 || opened.st_dev != file.st_dev ||
      opened.st_ino != file.st_ino) {
    const int failure = errno;
    if (descriptor >= 0) ::close(descriptor);
    ::unlink(temporary.c_str());
    fail(path, descriptor < 0 ? std::string("cannot open it to write: ") + std::strerror(failure)
                              : std::string("was replaced by another file while saving"));
  }
  const std::optional<std::string> old_text = read_all(descriptor);
  if (!old_text) {
    const int failure = errno;
    ::close(descriptor);
    ::unlink(temporary.c_str());
    fail(path, std::string("cannot read it before writing: ") + std::strerror(failure));
  }
  const int failure = overwrite(descriptor, contents);
  if (failure == 0) {
    ::close(descriptor);
    ::unlink(temporary.c_str());
    return;
  }
  const bool restored = overwrite(descriptor, *old_text) == 0;
  ::close(descriptor);
  if (restored) {
    ::unlink(temporary.c_str());
    fail(path, std::string("cannot write (") + std::strerror(failure) + "); its text is as before");
  }
  fail(path, std::string("cannot write (") + std::strerror(failure) +
                 "): it may be incomplete; the new text is in " + shown_path(temporary));
}

}  // namespace

void replace_file_keeping_identity(const std::string& path, const std::string& contents) {
  struct stat file {};
  if (::lstat(path.c_str(), &file) != 0)
    fail(path, std::string("cannot read its status: ") + std::strerror(errno));
  if (!S_ISREG(file.st_mode)) fail(path, "is not a regular file; not replaced");
  if (::faccessat(AT_FDCWD, path.c_str(), W_OK, AT_EACCESS) != 0)
    fail(path, "is not writable by this user (read-only); not replaced");
  Temporary temporary = temporary_beside(path, contents);
  // Extended attributes (ACLs, security labels) do not pass to a new file: such a file, one
  // with other hard links and one whose owner we cannot give away is written in place.
  const bool attributes = ::listxattr(path.c_str(), nullptr, 0) > 0;
  const bool renamable =
      file.st_nlink == 1 && !attributes && take_identity(temporary.descriptor, file);
  if (::close(temporary.descriptor) != 0) {
    const int failure = errno;
    ::unlink(temporary.path.c_str());
    fail(path, std::string("cannot write: ") + std::strerror(failure));
  }
  if (!renamable) {
    write_in_place(path, file, contents, temporary.path);
    return;
  }
  if (::rename(temporary.path.c_str(), path.c_str()) != 0) {
    const int failure = errno;
    ::unlink(temporary.path.c_str());
    fail(path, std::string("cannot rename into place: ") + std::strerror(failure));
  }
  sync_folder(path);
}

void write_file_atomically(const std::string& path, const std::string& contents) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::string temporary = (folder / ("." + target.filename().string() + ".XXXXXX")).string();
  const int descriptor = ::mkstemp(temporary.data());
  if (descriptor < 0)
    fail(path, std::string("cannot create a file beside it: ") + std::strerror(errno));
  // close(2) is checked too, as some file systems report errors only there.
  int failure = write_all(descriptor, contents);
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
