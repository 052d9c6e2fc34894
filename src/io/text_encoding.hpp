#pragma once
// Text files are UTF-8 (YAML 1.2, XML and the CSV logs all say so); a Latin-1 byte in a rig's
// name would otherwise travel to the JSON and JUnit reports and fail there. Private to io.
#include <string>
#include <string_view>

namespace rigdesign::io {

/// Throws InputError at the line and column of the first byte sequence of `text` that is not
/// UTF-8 (`file` names it), with the byte's value. A UTF-8 byte-order mark is accepted.
void require_utf8(std::string_view text, const std::string& file);

}  // namespace rigdesign::io
