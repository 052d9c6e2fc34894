#include "rigdesign/io/output_folder.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {

void prepare_output_folder(const std::string& folder, const std::string& option) {
  const auto fail = [&](const std::string& problem) {
    throw model::InputError(model::Diagnostic{
        {"(command line)", 0, 0}, option, "'" + folder + "' " + problem, "a writable folder"});
  };
  if (folder.empty()) fail("is empty");
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) fail("cannot be created: " + error.message());
  if (!std::filesystem::is_directory(folder, error)) fail("is not a folder");
  // The probe is what every output does: a temporary file beside the final name.
  std::string probe = (std::filesystem::path(folder) / ".rigdesign-probe.XXXXXX").string();
  const int descriptor = ::mkstemp(probe.data());
  if (descriptor < 0) fail(std::string("cannot hold a new file: ") + std::strerror(errno));
  ::close(descriptor);
  ::unlink(probe.c_str());
}

}  // namespace rigdesign::io
