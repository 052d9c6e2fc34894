#pragma once
#include <string>

namespace rigdesign::io {

/// Writes `contents` to a temporary file beside `path` and renames it over `path`, so a
/// reader never sees a half-written file and a failure leaves nothing behind.
/// Throws InputError (field "output") when the folder is not writable.
void write_file_atomically(const std::string& path, const std::string& contents);

}  // namespace rigdesign::io
