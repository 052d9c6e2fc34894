#pragma once
/// Text made safe inside XML and HTML: element content and attribute values alike (JUnit
/// reports, SVG <text>, the HTML report), and text made valid UTF-8 for any format.
#include <string>

namespace rigdesign::model {

/// `text` with & < > " ' replaced by their entities, and the control characters XML 1.0
/// cannot hold (below 0x20 but tab, newline and carriage return; DEL) by U+FFFD.
std::string xml_escaped(const std::string& text);

/// `text` with every byte sequence that is not UTF-8 replaced by U+FFFD: what XML, HTML and
/// YAML writers do with text that did not come from a checked file (a path on the command
/// line), so that the file they write stays readable by any parser.
std::string utf8_repaired(const std::string& text);

}  // namespace rigdesign::model
