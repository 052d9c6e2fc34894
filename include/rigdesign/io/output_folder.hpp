#pragma once
#include <string>

namespace rigdesign::io {

/// Creates `folder` with its parents and proves a file can be created in it, so a command
/// fails before its long work rather than after it. Throws InputError naming `option` (e.g.
/// "--out") with the operating system's reason (a regular file in the way, a read-only
/// folder, no space left).
void prepare_output_folder(const std::string& folder, const std::string& option);

}  // namespace rigdesign::io
