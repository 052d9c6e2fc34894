#include "rigdesign/io/file_bytes.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {
namespace {

// Larger inputs are refused rather than read: a pipe or a device (/dev/zero) has no end.
constexpr std::uintmax_t kMaxInputBytes = std::uintmax_t{4} << 30;

}  // namespace

std::string read_file_bytes(const std::string& path, const std::string& expected) {
  namespace fs = std::filesystem;
  const auto fail = [&](const std::string& problem) {
    throw model::InputError(model::Diagnostic{{path, 0, 0}, "file", problem, expected});
  };
  std::error_code ignored;
  const fs::file_status status = fs::status(path, ignored);
  if (fs::is_directory(status)) fail("is a folder");
  // A device never ends (/dev/zero) or never answers; a pipe (process substitution) is read.
  if (fs::is_character_file(status) || fs::is_block_file(status) || fs::is_socket(status))
    fail("is a device or socket, not a file");
  std::ifstream stream(path, std::ios::binary);
  if (!stream) fail(std::string("cannot be opened: ") + std::strerror(errno));
  std::string bytes;
  if (fs::is_regular_file(status)) {
    // One read of the known size: real clouds are megabytes.
    const std::uintmax_t size = fs::file_size(path, ignored);
    if (size > kMaxInputBytes) fail("is larger than 4 GiB");
    bytes.resize(static_cast<std::size_t>(size));
    stream.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!stream) fail("cannot be read to its end");
    return bytes;
  }
  // A pipe (process substitution, /dev/stdin): read in blocks up to the limit.
  char block[1 << 16];
  while (stream.read(block, sizeof block) || stream.gcount() > 0) {
    bytes.append(block, static_cast<std::size_t>(stream.gcount()));
    if (bytes.size() > kMaxInputBytes) fail("is larger than 4 GiB");
  }
  return bytes;
}

}  // namespace rigdesign::io
