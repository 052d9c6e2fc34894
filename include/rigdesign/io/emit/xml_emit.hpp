#pragma once
// How io's writers put text into XML (the exported xacro): attribute values and comments go
// through one function each, so what reaches a file is escaped in one place.
#include <string>

namespace rigdesign::io {

/// `text` escaped for an attribute value or element content (& < > " ').
std::string xml_attribute(const std::string& text);
/// `text` as a literal in a xacro attribute: xml_attribute, and every run of '$' before '{'
/// or '(' doubled once, which xacro reads back as the run itself (a link named `a${b}` is
/// not evaluated as an expression).
std::string xacro_literal(const std::string& text);
/// `text` as the lines of a comment's body, each prefixed by `indent`; "--", which may not
/// appear inside an XML comment, is written "- -".
std::string xml_comment_lines(const std::string& text, const std::string& indent);
/// `text` inside a one-line comment: line breaks become spaces, "--" is written "- -".
std::string xml_comment_line(const std::string& text);

}  // namespace rigdesign::io
