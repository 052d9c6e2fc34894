#pragma once
// A whole file read in one go: every reader of a user's file (YAML, URDF, clouds, meshes, logs)
// and the pages that inline written pictures.
#include <optional>
#include <string>

namespace rigdesign::io {

/// The file's bytes. Throws InputError (field "file", `expected` as the expected form) when the
/// path is not a regular file (a folder, a FIFO, a socket or a device is refused at once with
/// what it is, never opened to wait), cannot be opened, or cannot be read to its end.
/// What `path` is when it exists and is not a regular file ("is a pipe (FIFO), ..."), else
/// nothing: for readers that must refuse before a library opens the path.
std::optional<std::string> not_a_regular_file(const std::string& path);

std::string read_file_bytes(const std::string& path, const std::string& expected);

}  // namespace rigdesign::io
