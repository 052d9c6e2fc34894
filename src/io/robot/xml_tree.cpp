#include "xml_tree.hpp"

#include <tinyxml2.h>
#include <unistd.h>

#include "io/text_encoding.hpp"
#include "rigdesign/io/file_bytes.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io::xml {
namespace {

Node convert(const tinyxml2::XMLElement& element, const std::string& file) {
  Node node;
  node.name = element.Name();
  node.where = {file, element.GetLineNum(), 0};
  for (const tinyxml2::XMLAttribute* a = element.FirstAttribute(); a; a = a->Next()) {
    node.attributes.emplace_back(a->Name(), a->Value());
  }
  for (const tinyxml2::XMLNode* child = element.FirstChild(); child; child = child->NextSibling()) {
    if (const tinyxml2::XMLElement* e = child->ToElement()) {
      node.children.push_back(convert(*e, file));
    } else if (const tinyxml2::XMLText* t = child->ToText()) {
      Node text;
      text.kind = Node::Kind::text;
      text.text = t->Value();
      text.where = {file, t->GetLineNum(), 0};
      node.children.push_back(std::move(text));
    }
  }
  return node;
}

void escape(const std::string& text, bool attribute, std::string& out) {
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += attribute ? "&quot;" : "\""; break;
      default: out += c;
    }
  }
}

void write(const Node& node, std::string& out) {
  if (node.kind == Node::Kind::text) {
    escape(node.text, false, out);
    return;
  }
  out += '<' + node.name;
  for (const auto& [key, value] : node.attributes) {
    out += ' ' + key + "=\"";
    escape(value, true, out);
    out += '"';
  }
  if (node.children.empty()) {
    out += "/>";
    return;
  }
  out += '>';
  for (const Node& child : node.children) write(child, out);
  out += "</" + node.name + '>';
}

}  // namespace

const std::string* Node::attribute(const std::string& key) const {
  for (const auto& [attribute_name, value] : attributes) {
    if (attribute_name == key) return &value;
  }
  return nullptr;
}

Node parse_file(const std::string& path, const model::SourceLocation& named_at,
                const std::string& field) {
  // Judged without opening: opening a FIFO would wait for a writer.
  if (const std::optional<std::string> kind = not_a_regular_file(path)) {
    throw model::InputError(model::Diagnostic{
        named_at, field, "names '" + path + "', which " + *kind, "an existing URDF or xacro file"});
  }
  if (::access(path.c_str(), R_OK) != 0) {
    throw model::InputError(model::Diagnostic{named_at, field,
                                              "names '" + path + "', which cannot be read",
                                              "an existing URDF or xacro file"});
  }
  // The shared reader: bounded size, pipes and read errors reported against the file itself.
  return parse_text(read_file_bytes(path, "a URDF or xacro file"), path);
}

Node parse_text(const std::string& text, const std::string& file) {
  require_utf8(text, file);
  tinyxml2::XMLDocument document(true, tinyxml2::COLLAPSE_WHITESPACE);
  if (document.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS) {
    const char* detail = document.ErrorStr();
    throw model::InputError(model::Diagnostic{
        {file, document.ErrorLineNum(), 0},
        "xml",
        std::string("is not well-formed XML: ") + (detail ? detail : "parse error"),
        "a robot description in XML (URDF or xacro)"});
  }
  const tinyxml2::XMLElement* root = document.RootElement();
  if (!root) {
    throw model::InputError(
        model::Diagnostic{{file, 1, 1}, "xml", "has no root element", "a <robot> element"});
  }
  return convert(*root, file);
}

std::string to_xml(const Node& root) {
  std::string out = "<?xml version=\"1.0\"?>\n";
  write(root, out);
  out += '\n';
  return out;
}

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

}  // namespace rigdesign::io::xml
