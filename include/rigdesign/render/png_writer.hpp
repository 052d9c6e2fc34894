#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace rigdesign::render {

/// Writes an RGBA image (8 bits per channel, rows top to bottom, width * height * 4 bytes)
/// as PNG, atomically (temporary file beside `path`, then rename). Throws InputError
/// (field "output") when the folder is not writable.
void write_png_rgba(const std::string& path, int width, int height,
                    const std::vector<std::uint8_t>& rgba);

}  // namespace rigdesign::render
