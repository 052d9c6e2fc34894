#pragma once
// A whole file read in one go: the binary-capable readers (clouds, meshes) and the pages that
// inline written pictures.
#include <string>

namespace rigdesign::io {

/// The file's bytes. Throws InputError (field "file", `expected` as the expected form) when the
/// path is a folder, cannot be opened or cannot be read to its end.
std::string read_file_bytes(const std::string& path, const std::string& expected);

}  // namespace rigdesign::io
