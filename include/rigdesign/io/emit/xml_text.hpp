#pragma once
/// Text made safe inside XML and HTML: element content and attribute values alike (JUnit
/// reports, SVG <text>, the HTML report), and text made valid UTF-8 for any format.
#include <string>
#include <string_view>

namespace rigdesign::io {

/// `text` with & < > " ' replaced by their entities, and the control characters XML 1.0
/// cannot hold (below 0x20 but tab, newline and carriage return; DEL) by U+FFFD.
std::string xml_escaped(const std::string& text);

/// `text` with every byte sequence that is not UTF-8 replaced by U+FFFD: what XML, HTML and
/// YAML writers do with text that did not come from a checked file (a path on the command
/// line), so that the file they write stays readable by any parser.
std::string utf8_repaired(const std::string& text);

/// Length of the well-formed UTF-8 sequence at text[i] (RFC 3629: no overlong forms, no
/// surrogates, nothing above U+10FFFF), or 0 when it is not one. The one decoder behind
/// utf8_repaired and the readers' UTF-8 check (io/text_encoding).
std::size_t utf8_sequence_length(std::string_view text, std::size_t i);

}  // namespace rigdesign::io
