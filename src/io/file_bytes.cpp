#include "rigdesign/io/file_bytes.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {
namespace {

// Larger inputs are refused rather than read: real clouds and meshes are megabytes.
constexpr std::uintmax_t kMaxInputBytes = std::uintmax_t{4} << 30;

// What a path holds when it is not a regular file, in the words a user knows.
std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "is a folder";
  if (S_ISFIFO(mode)) return "is a pipe (FIFO), not a file: it would wait for a writer";
  if (S_ISSOCK(mode)) return "is a socket, not a file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a file";
  return "is not a regular file";
}

// Closes the descriptor on every path out of read_file_bytes.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::optional<std::string> not_a_regular_file(const std::string& path) {
  struct stat named {};
  if (::stat(path.c_str(), &named) != 0 || S_ISREG(named.st_mode)) return std::nullopt;
  return kind_of(named.st_mode);
}

std::string read_file_bytes(const std::string& path, const std::string& expected) {
  const auto fail = [&](const std::string& problem) {
    throw model::InputError(model::Diagnostic{{path, 0, 0}, "file", problem, expected});
  };
  // Judged before opening where possible: open(2) of a socket fails with a vague ENXIO.
  if (const std::optional<std::string> kind = not_a_regular_file(path)) fail(*kind);
  // O_NONBLOCK: a FIFO put in place after the stat above must not block the open; the opened
  // file is judged again, so only a regular file is ever read.
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC)};
  if (file.fd < 0) fail(std::string("cannot be opened: ") + std::strerror(errno));
  struct stat opened {};
  if (::fstat(file.fd, &opened) != 0) fail(std::string("cannot be read: ") + std::strerror(errno));
  if (!S_ISREG(opened.st_mode)) fail(kind_of(opened.st_mode));
  if (static_cast<std::uintmax_t>(opened.st_size) > kMaxInputBytes) fail("is larger than 4 GiB");
  std::string bytes(static_cast<std::size_t>(opened.st_size), '\0');
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t got = ::read(file.fd, bytes.data() + done, bytes.size() - done);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) fail(std::string("cannot be read to its end: ") + std::strerror(errno));
    if (got == 0) break;  // shrank while read: what is there is the file
    done += static_cast<std::size_t>(got);
  }
  bytes.resize(done);
  return bytes;
}

}  // namespace rigdesign::io
