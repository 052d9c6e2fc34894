#pragma once
// How io's writers put text into YAML: comments, keys and scalars each go through one function
// here, so what reaches a file is quoted or escaped in one place (STYLE.md, "foreign formats").
#include <ostream>
#include <string>
#include <string_view>

namespace rigdesign::io {

/// `text` as comment lines: `indent` + "# " + line, one per line of `text`.
std::string yaml_comment(const std::string& text, const std::string& indent = "");
/// A scalar for a key or a value: plain when YAML reads it back as the same string (a ROS
/// name, a topic, a frame), else double-quoted with `"` and `\` escaped.
std::string yaml_scalar(const std::string& text);
/// Always double-quoted, `"` and `\` escaped: names that look like other types or hold `::`.
std::string yaml_quoted(const std::string& text);
/// A number rclcpp reads as a double (exact digits, ".0" added to a whole number): ROS 2
/// refuses an integer for a parameter declared double.
std::string yaml_float(double value);
/// `true` or `false`.
std::string yaml_bool(bool value);
/// `indent` + `key: value` on a line of its own, `comment` (one line) after it when given.
/// `value` is already YAML (from the functions above).
void write_key(std::ostream& out, const std::string& indent, std::string_view key,
               const std::string& value, const std::string& comment = "");

}  // namespace rigdesign::io
