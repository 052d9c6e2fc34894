#pragma once
// Shared by the fuzz targets (libFuzzer): hand the fuzzer's bytes to a reader the way the CLI
// does, and tell an expected refusal from a finding.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "rigdesign/model/input_error.hpp"

namespace rigdesign::fuzz {

/// The fuzzer's bytes as text.
inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// Writes the bytes to `name` in this process's scratch folder (on /dev/shm when it exists,
/// so a run does not wear the disk) and returns its path. Readers that take a path, and pick
/// the format by extension, get a real file.
std::string input_file(const std::uint8_t* data, std::size_t size, const std::string& name);

/// Path of `name` in the scratch folder, for fixed companion files (a map's YAML beside the
/// fuzzed image).
std::string scratch_path(const std::string& name);

/// Aborts (a finding) unless every diagnostic names a file and says what is wrong: the
/// project's promise for bad input.
void require_clear_message(const model::InputError& error);

/// Runs `read`. InputError is the expected answer to bad input; any other exception escapes
/// and libFuzzer reports it, as it does crashes, leaks, undefined behaviour and timeouts.
template <class Read>
int expect_input_errors(Read&& read) {
  try {
    read();
  } catch (const model::InputError& error) {
    require_clear_message(error);
  }
  return 0;
}

}  // namespace rigdesign::fuzz
