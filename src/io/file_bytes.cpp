#include "io/file_bytes.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {

std::string read_file_bytes(const std::string& path, const std::string& expected) {
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) {
    throw model::InputError(model::Diagnostic{{path, 0, 0}, "file", "is a folder", expected});
  }
  std::ifstream stream(path, std::ios::binary | std::ios::ate);
  if (!stream) {
    throw model::InputError(model::Diagnostic{
        {path, 0, 0}, "file", std::string("cannot be opened: ") + std::strerror(errno), expected});
  }
  // One read of the known size: real clouds are megabytes.
  std::string bytes(static_cast<std::size_t>(stream.tellg()), '\0');
  stream.seekg(0);
  stream.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!stream) {
    throw model::InputError(
        model::Diagnostic{{path, 0, 0}, "file", "cannot be read to its end", expected});
  }
  return bytes;
}

}  // namespace rigdesign::io
