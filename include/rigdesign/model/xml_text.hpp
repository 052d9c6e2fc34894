#pragma once
/// Text made safe inside XML and HTML: element content and attribute values alike (JUnit
/// reports, SVG <text>, the HTML report).
#include <string>

namespace rigdesign::model {

/// `text` with & < > " ' replaced by their entities, and the control characters XML 1.0
/// cannot hold (below 0x20 but tab, newline and carriage return; DEL) by U+FFFD.
std::string xml_escaped(const std::string& text);

}  // namespace rigdesign::model
