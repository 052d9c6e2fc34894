#include "fuzz_input.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace rigdesign::fuzz {
namespace {

// One folder per process (libFuzzer's -jobs runs several), removed at exit.
class ScratchFolder {
 public:
  ScratchFolder() {
    std::error_code error;
    const std::filesystem::path shm = "/dev/shm";
    const std::filesystem::path base =
        std::filesystem::is_directory(shm, error) ? shm : std::filesystem::temp_directory_path();
    path_ = base / ("rigdesign-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

const ScratchFolder& scratch() {
  static const ScratchFolder folder;
  return folder;
}

}  // namespace

std::string scratch_path(const std::string& name) {
  return (scratch().path() / name).string();
}

std::string input_file(const std::uint8_t* data, std::size_t size, const std::string& name) {
  const std::string path = scratch_path(name);
  std::ofstream stream(path, std::ios::binary | std::ios::trunc);
  stream.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  stream.close();
  if (!stream) {
    std::fprintf(stderr, "fuzz harness: cannot write %s\n", path.c_str());
    std::abort();
  }
  return path;
}

void require_clear_message(const model::InputError& error) {
  if (error.diagnostics().empty()) {
    std::fprintf(stderr, "finding: InputError without a diagnostic\n");
    std::abort();
  }
  for (const model::Diagnostic& diagnostic : error.diagnostics()) {
    if (diagnostic.where.file.empty() || diagnostic.problem.empty()) {
      std::fprintf(stderr, "finding: a diagnostic without a file or a problem: %s\n",
                   diagnostic.message().c_str());
      std::abort();
    }
  }
}

}  // namespace rigdesign::fuzz

// assimp 5.2 (Debian 12) leaks a few objects on some malformed STL and COLLADA files; the
// leaks are inside the library, which rigdesign cannot fix. Only allocations made there are
// suppressed: leaks in rigdesign's own code are still findings.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libassimp.so\n";
}
