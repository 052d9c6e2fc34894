#pragma once
/// A plain XML tree that remembers where each element came from (file and line), so the
/// xacro expander can copy macro bodies and included files around and still point an
/// error at the line a user wrote. tinyxml2 parses; this tree is what the expander edits.
#include <string>
#include <utility>
#include <vector>

#include "rigdesign/model/source_location.hpp"

namespace rigdesign::io::xml {

struct Node {
  enum class Kind { element, text };
  Kind kind = Kind::element;
  std::string name;                                             ///< element tag, e.g. "xacro:macro"
  std::vector<std::pair<std::string, std::string>> attributes;  ///< in document order
  std::vector<Node> children;
  std::string text;  ///< a text node's content
  model::SourceLocation where;

  const std::string* attribute(const std::string& key) const;
  bool is_element(const std::string& tag) const { return kind == Kind::element && name == tag; }
};

/// Reads and parses `path`. Comments, processing instructions and the XML declaration are
/// dropped; text nodes keep their content. Throws InputError at `named_at` when the file
/// cannot be read, and at the file's line when it is not well-formed XML.
Node parse_file(const std::string& path, const model::SourceLocation& named_at,
                const std::string& field);

/// Parses XML held in memory; `file` names it in errors (e.g. the xacro file it came from).
Node parse_text(const std::string& text, const std::string& file);

/// `text` without the XML whitespace (space, tab, CR, LF) around it.
std::string trimmed(const std::string& text);

/// Serialises `root` (an element) as an XML document, escaping text and attribute values.
std::string to_xml(const Node& root);

}  // namespace rigdesign::io::xml
