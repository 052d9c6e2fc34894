#pragma once
// How io's writers put text into Python source (the exported launch file): every string goes
// through one function here (STYLE.md, "foreign formats").
#include <string>

namespace rigdesign::io {

/// A single-quoted Python string literal holding `text` exactly: `\` and `'` escaped, and
/// every byte outside printable ASCII written as \xNN (a newline in a topic cannot end the
/// string or the line).
std::string python_string(const std::string& text);

/// `text` as Python comment lines: "# " + line, one per line of `text`; bytes outside
/// printable ASCII become `?`.
std::string python_comment(const std::string& text);

}  // namespace rigdesign::io
