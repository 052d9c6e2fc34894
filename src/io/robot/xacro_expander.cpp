#include "xacro_expander.hpp"

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

#include "rigdesign/io/robot/xacro_expression.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {
namespace {

namespace fs = std::filesystem;
using xacro::Value;

// Bounds on the work one description may ask for. Real xacro stops a self-calling macro
// with an error but lets doubling properties, macros or includes run until memory runs out;
// rigdesign refuses them at the line where the limit is crossed. Each bound is far above
// what real descriptions need: the TurtleBot 4 and the Jackal with both accessories expand
// to under 300 elements, 60 includes, nesting under 10 and values under 200 bytes.
// Macro calls, block insertions, includes and property references nested deeper than this
// are taken as a definition that uses itself without end (each level costs stack).
constexpr int kMaxNesting = 100;
// Elements and text nodes the expansion may produce (each costs a node and its source line).
constexpr std::size_t kMaxNodes = 200000;
// Macro calls in all (a macro that defines only properties produces no node), and includes
// (each reads and copies a file: 10,000 take about 0.2 s; real descriptions include dozens).
constexpr std::size_t kMaxExpansions = 200000;
constexpr std::size_t kMaxIncludes = 10000;
// Bytes of one evaluated text (a property or attribute value), and of all text produced.
constexpr std::size_t kMaxTextBytes = std::size_t{1} << 20;
constexpr std::size_t kMaxTotalTextBytes = std::size_t{64} << 20;
const std::string kPrefix = "xacro:";
const std::set<std::string> kIgnoredElements = {"gazebo", "ros2_control", "transmission"};

struct Scope;

// A property or macro parameter: a text evaluated on first use (xacro's lazy properties),
// a value, or a block of XML (block properties and * / ** parameters).
struct Property {
  std::optional<std::string> raw;
  std::optional<Value> value;
  std::vector<xml::Node> block;
  bool is_block = false;
  bool block_expanded = false;  // a macro's block argument, expanded in the caller's scope
  bool evaluating = false;
  Scope* defined_in = nullptr;
  model::SourceLocation where;
};

struct Parameter {
  std::string name;
  enum class Kind { plain, block, content_block } kind = Kind::plain;
  std::optional<std::string> default_text;
  bool from_caller = false;  // ":=^": take the caller's property of the same name
};

struct Macro {
  std::string name;
  std::vector<Parameter> parameters;
  xml::Node body;
};

struct Scope {
  Scope* parent = nullptr;
  std::map<std::string, Property> properties;
  std::map<std::string, std::shared_ptr<const Macro>> macros;

  Property* property(const std::string& name) {
    for (Scope* s = this; s; s = s->parent) {
      if (auto it = s->properties.find(name); it != s->properties.end()) return &it->second;
    }
    return nullptr;
  }
  std::shared_ptr<const Macro> macro(const std::string& name) const {
    for (const Scope* s = this; s; s = s->parent) {
      if (auto it = s->macros.find(name); it != s->macros.end()) return it->second;
    }
    return nullptr;
  }
  Scope& root() {
    Scope* s = this;
    while (s->parent) s = s->parent;
    return *s;
  }
};

[[noreturn]] void fail(const model::SourceLocation& where, const std::string& problem,
                       const std::string& expected = {}) {
  throw model::InputError(model::Diagnostic{where, "xacro", problem, expected});
}

std::vector<std::string> words_of(const std::string& text) {
  std::vector<std::string> words;
  std::istringstream stream(text);
  for (std::string word; stream >> word;) words.push_back(word);
  return words;
}

// xacro's reading of a conditional's value (xacro's get_boolean_value).
bool condition_holds(const Value& value, const std::string& written,
                     const model::SourceLocation& where) {
  if (value.kind != Value::Kind::text) return xacro::truthy(value);
  if (value.text == "true" || value.text == "True") return true;
  if (value.text == "false" || value.text == "False") return false;
  const Value literal = xacro::parse_literal(value.text);
  if (literal.kind == Value::Kind::integer) return literal.integer != 0;
  fail(where, "the condition '" + written + "' evaluated to '" + value.text + "'",
       "a boolean: true, false, 1, 0 or an expression such as ${x == 'y'}");
}

std::vector<Parameter> parse_parameters(const std::string& text,
                                        const model::SourceLocation& where) {
  std::vector<Parameter> parameters;
  for (const std::string& word : words_of(text)) {
    Parameter p;
    std::string name = word;
    if (const auto assign = word.find(":="); assign != std::string::npos) {
      name = word.substr(0, assign);
      std::string fallback = word.substr(assign + 2);
      if (fallback.rfind('^', 0) == 0) {
        p.from_caller = true;
        if (fallback.size() > 1 && fallback[1] == '|') p.default_text = fallback.substr(2);
      } else {
        p.default_text = fallback;
      }
    } else if (const auto equals = word.find('='); equals != std::string::npos) {
      fail(where, "macro parameter '" + word + "' uses '='", "name:=default");
    }
    if (name.rfind("**", 0) == 0) {
      p.kind = Parameter::Kind::content_block;
      name = name.substr(2);
    } else if (name.rfind('*', 0) == 0) {
      p.kind = Parameter::Kind::block;
      name = name.substr(1);
    }
    if (name.empty()) fail(where, "an empty macro parameter name in '" + text + "'");
    p.name = name;
    parameters.push_back(std::move(p));
  }
  return parameters;
}

std::string folder_of(const std::string& file) {
  return fs::path(file).parent_path().string();
}

class Expander {
  // One level of nesting (macro call, block insertion, include, property reference), undone
  // when the level ends; throws past kMaxNesting naming the line that went one level deeper.
  class Nesting {
   public:
    Nesting(Expander& expander, const model::SourceLocation& where, const std::string& what)
        : expander_(expander) {
      if (++expander_.depth_ > kMaxNesting) {
        fail(where,
             what + " is reached through more than " + std::to_string(kMaxNesting) +
                 " nested macro calls, blocks, includes or property references (a "
                 "definition that uses itself?)",
             "macros, blocks, includes and properties that do not refer back to themselves");
      }
    }
    ~Nesting() { --expander_.depth_; }
    Nesting(const Nesting&) = delete;
    Nesting& operator=(const Nesting&) = delete;

   private:
    Expander& expander_;
  };

 public:
  explicit Expander(const XacroInput& input) : input_(input), args_(input.args) {}

  xml::Node run() {
    const xml::Node& document = parse(input_.path, input_.named_at);
    include_stack_.push_back(fs::weakly_canonical(input_.path).string());
    xml::Node root;
    root.name = document.name;
    root.where = document.where;
    Scope global;
    for (const auto& [key, value] : document.attributes) {
      if (key.rfind("xmlns", 0) == 0) continue;
      root.attributes.emplace_back(key, text_of(value, global, document.where));
    }
    expand_children(document, global, root.children);
    return root;
  }

 private:
  const xml::Node& parse(const std::string& path, const model::SourceLocation& named_at) {
    const std::string key = fs::weakly_canonical(path).string();
    auto it = parsed_.find(key);
    if (it == parsed_.end()) {
      it = parsed_.emplace(key, xml::parse_file(path, named_at, "xacro:include")).first;
    }
    return it->second;
  }

  // ---- text: ${expressions}, $(substitutions), $$ escapes ----

  Value evaluate_text(const std::string& text, Scope& scope, const model::SourceLocation& where) {
    std::vector<Value> parts;
    std::size_t i = 0;
    while (i < text.size()) {
      if (text.compare(i, 2, "$$") == 0) {  // "$${" is a literal "${"
        std::size_t end = i;
        while (end < text.size() && text[end] == '$') ++end;
        if (end < text.size() && (text[end] == '{' || text[end] == '(')) {
          parts.push_back(Value::of_text(text.substr(i + 1, end - i)));
          i = end;
          continue;
        }
      }
      if (text.compare(i, 2, "${") == 0 || text.compare(i, 2, "$(") == 0) {
        const char close = text[i + 1] == '{' ? '}' : ')';
        const std::size_t end = text.find(close, i + 2);
        if (end == std::string::npos) {
          fail(where, "'" + text + "' has no closing '" + close + "'");
        }
        const std::string inner =
            xacro::to_text(evaluate_text(text.substr(i + 2, end - i - 2), scope, where));
        parts.push_back(close == '}' ? expression(inner, scope, where)
                                     : Value::of_text(substitution(inner, where)));
        i = end + 1;
        continue;
      }
      std::size_t next = text.find('$', i + 1);
      if (next == std::string::npos) next = text.size();
      parts.push_back(Value::of_text(text.substr(i, next - i)));
      i = next;
    }
    if (parts.size() == 1) return bounded(parts.front(), where);
    std::string joined;
    for (const Value& part : parts) {
      joined += xacro::to_text(part);
      bounded(joined, where);
    }
    return Value::of_text(joined);
  }

  // Checked as texts grow, so that doubling properties stop at the first oversized value.
  void bounded(const std::string& text, const model::SourceLocation& where) const {
    if (text.size() > kMaxTextBytes) {
      fail(where,
           "a value expands to more than " + std::to_string(kMaxTextBytes >> 20) +
               " MiB of text (properties that double themselves?)",
           "values of at most 1 MiB");
    }
  }
  const Value& bounded(const Value& value, const model::SourceLocation& where) const {
    if (value.kind == Value::Kind::text) bounded(value.text, where);
    return value;
  }

  std::string text_of(const std::string& text, Scope& scope, const model::SourceLocation& where) {
    std::string result = xacro::to_text(evaluate_text(text, scope, where));
    text_bytes_ += result.size();
    if (text_bytes_ > kMaxTotalTextBytes) {
      fail(where,
           "the expansion produces more than " + std::to_string(kMaxTotalTextBytes >> 20) +
               " MiB of text",
           "a description that expands to less (macros or properties that multiply?)");
    }
    return result;
  }

  // Every node the expansion emits (a copied subtree counts each of its nodes).
  void produced(const xml::Node& node) {
    nodes_ += 1;
    for (const xml::Node& child : node.children) produced(child);
    if (nodes_ > kMaxNodes) {
      fail(node.where,
           "the expansion produces more than " + std::to_string(kMaxNodes) +
               " elements (macros or blocks that multiply?)",
           "a description that expands to fewer elements");
    }
  }

  void expanded_once_more(const model::SourceLocation& where, const std::string& what) {
    std::size_t& count = what == "includes" ? includes_ : expansions_;
    const std::size_t limit = what == "includes" ? kMaxIncludes : kMaxExpansions;
    if (++count > limit) {
      fail(where,
           "more than " + std::to_string(limit) + " " + what +
               " in all (macros or includes that multiply?)",
           "a description that calls and includes less");
    }
  }

  Value expression(const std::string& expression_text, Scope& scope,
                   const model::SourceLocation& where) {
    const xacro::Lookup lookup = [&](const std::string& name) -> std::optional<Value> {
      Property* property = scope.property(name);
      if (!property) return std::nullopt;
      return resolve(name, *property, where);
    };
    try {
      return xacro::evaluate(expression_text, lookup);
    } catch (const xacro::ExpressionError& error) {
      fail(where, "in ${" + expression_text + "}: " + error.what(),
           "a Python expression over the defined properties and arguments");
    }
  }

  Value resolve(const std::string& name, Property& property, const model::SourceLocation& used_at) {
    if (property.value) return *property.value;
    if (property.is_block) {
      fail(used_at, "'" + name + "' is a block, not a value",
           "<xacro:insert_block name=\"" + name + "\"/> to insert it");
    }
    if (property.evaluating) fail(property.where, "property '" + name + "' refers to itself");
    property.evaluating = true;
    const Nesting level(*this, used_at, "property '" + name + "'");
    const Value text = evaluate_text(*property.raw, *property.defined_in, property.where);
    property.evaluating = false;
    property.value = text.kind == Value::Kind::text ? xacro::parse_literal(text.text) : text;
    return *property.value;
  }

  std::string environment(const std::string& name) const {
    if (const auto it = input_.environment.find(name); it != input_.environment.end())
      return it->second;
    const char* value = std::getenv(name.c_str());
    return value ? value : "";
  }

  bool has_environment(const std::string& name) const {
    return input_.environment.count(name) || std::getenv(name.c_str());
  }

  std::string substitution(const std::string& inner, const model::SourceLocation& where) {
    const std::vector<std::string> words = words_of(inner);
    const std::string command = words.empty() ? "" : words.front();
    const auto rest_from = [&](std::size_t first) {
      std::string rest;
      for (std::size_t k = first; k < words.size(); ++k) rest += (k > first ? " " : "") + words[k];
      return rest;
    };
    if (command == "arg" && words.size() == 2) {
      const auto it = args_.find(words[1]);
      if (it == args_.end()) {
        fail(where, "$(arg " + words[1] + ") is not defined",
             "an <xacro:arg name=\"" + words[1] +
                 "\" default=\"...\"/> before this line, or robot.args." + words[1] +
                 " in the rig");
      }
      return it->second;
    }
    if (command == "find" && words.size() == 2) {
      if (const auto folder = input_.packages->find(words[1])) return *folder;
      std::string searched;
      for (const std::string& root : input_.packages->searched())
        searched += (searched.empty() ? "" : ", ") + root;
      fail(where,
           "package '" + words[1] +
               "' not found (searched: " + (searched.empty() ? "no folder" : searched) + ")",
           "a folder whose package.xml names " + words[1] +
               " under the rig's robot.package_paths, ROS_PACKAGE_PATH or AMENT_PREFIX_PATH");
    }
    if ((command == "optenv" || command == "env") && words.size() >= 2 && input_.environment_read)
      input_.environment_read->insert(words[1]);
    if (command == "optenv" && words.size() >= 2) {
      return has_environment(words[1]) ? environment(words[1]) : rest_from(2);
    }
    if (command == "env" && words.size() == 2) {
      if (!has_environment(words[1])) {
        fail(where, "$(env " + words[1] + ") is not set",
             "the variable in robot.env of the rig, or $(optenv " + words[1] + " default)");
      }
      return environment(words[1]);
    }
    if (command == "dirname" && words.size() == 1) return folder_of(where.file);
    fail(where, "the substitution $(" + inner + ") is not understood",
         "$(arg NAME), $(find PKG), $(optenv VAR [default]), $(env VAR) or $(dirname)");
  }

  // ---- elements ----

  void expand_children(const xml::Node& parent, Scope& scope, std::vector<xml::Node>& out) {
    for (const xml::Node& child : parent.children) expand_node(child, scope, out);
  }

  void expand_node(const xml::Node& node, Scope& scope, std::vector<xml::Node>& out) {
    if (node.kind == xml::Node::Kind::text) {
      xml::Node text = node;
      text.text = text_of(node.text, scope, node.where);
      produced(text);
      out.push_back(std::move(text));
      return;
    }
    if (node.name.rfind(kPrefix, 0) != 0) {
      // Simulator and controller configuration: URDF parsers skip it and so does rigdesign,
      // unexpanded, so that a plugin's $(find PKG) for a package this machine lacks (Gazebo
      // plugins, ros2_control configs) does not stop a description from loading.
      const bool kept = input_.keep_simulation || (input_.keep_gazebo && node.name == "gazebo" &&
                                                   node.attribute("reference"));
      if (!kept && kIgnoredElements.count(node.name)) return;
      xml::Node element;
      element.name = node.name;
      element.where = node.where;
      for (const auto& [key, value] : node.attributes) {
        element.attributes.emplace_back(key, text_of(value, scope, node.where));
      }
      expand_children(node, scope, element.children);
      nodes_ += 1;  // its children were counted as they were made
      produced_count_check(element.where);
      out.push_back(std::move(element));
      return;
    }
    const std::string keyword = node.name.substr(kPrefix.size());
    if (keyword == "include") return include(node, scope, out);
    if (keyword == "property") return define_property(node, scope);
    if (keyword == "arg") return define_argument(node, scope);
    if (keyword == "macro") return define_macro(node, scope);
    if (keyword == "if" || keyword == "unless") {
      const std::string& written = required(node, "value");
      const bool holds =
          condition_holds(evaluate_text(written, scope, node.where), written, node.where);
      if (holds == (keyword == "if")) expand_children(node, scope, out);
      return;
    }
    if (keyword == "insert_block") return insert_block(node, scope, out);
    if (keyword == "element") return element(node, scope, out);
    call_macro(node, keyword, scope, out);
  }

  const std::string& required(const xml::Node& node, const std::string& attribute) {
    const std::string* value = node.attribute(attribute);
    if (!value) {
      fail(node.where, "<" + node.name + "> has no " + attribute + " attribute",
           "<" + node.name + " " + attribute + "=\"...\">");
    }
    return *value;
  }

  void include(const xml::Node& node, Scope& scope, std::vector<xml::Node>& out) {
    if (node.attribute("ns")) {
      fail(node.where, "xacro:include with ns= (namespaced macros) is not supported",
           "an include without ns");
    }
    std::string file = text_of(required(node, "filename"), scope, node.where);
    if (const auto resolved = input_.packages->resolve_uri(file)) file = *resolved;
    if (fs::path(file).is_relative()) file = (fs::path(folder_of(node.where.file)) / file).string();
    std::error_code error;
    if (!fs::is_regular_file(file, error)) {
      fail(node.where, "the included file '" + file + "' does not exist",
           "a path relative to this file, or $(find PKG)/...");
    }
    const std::string key = fs::weakly_canonical(file).string();
    for (const std::string& open : include_stack_) {
      if (open == key) {
        std::string chain;
        for (const std::string& f : include_stack_) chain += f + " -> ";
        fail(node.where, "include cycle: " + chain + key, "files that do not include each other");
      }
    }
    const Nesting level(*this, node.where, "include of '" + file + "'");
    expanded_once_more(node.where, "includes");
    const xml::Node document = parse(file, node.where);  // a copy: parsed_ may grow below
    include_stack_.push_back(key);
    expand_children(document, scope, out);
    include_stack_.pop_back();
  }

  void define_property(const xml::Node& node, Scope& scope) {
    const std::string& name = required(node, "name");
    Scope* target = &scope;
    if (const std::string* where = node.attribute("scope")) {
      if (*where == "parent") {
        target = scope.parent ? scope.parent : &scope;
      } else if (*where == "global") {
        target = &scope.root();
      } else {
        fail(node.where, "scope=\"" + *where + "\" is not understood", "parent or global");
      }
    }
    Property property;
    property.defined_in = &scope;
    property.where = node.where;
    if (const std::string* value = node.attribute("value")) {
      property.raw = *value;
    } else if (const std::string* fallback = node.attribute("default")) {
      if (scope.property(name)) return;  // a default never replaces a defined value
      property.raw = *fallback;
    } else {
      property.is_block = true;
      for (const xml::Node& child : node.children) {
        if (child.kind == xml::Node::Kind::element) property.block.push_back(child);
      }
    }
    const std::string* lazy = node.attribute("lazy_eval");
    const bool now = (lazy && *lazy == "false") || target != &scope;
    target->properties[name] = std::move(property);
    if (now && !target->properties[name].is_block) {
      resolve(name, target->properties[name], node.where);
    }
  }

  void define_argument(const xml::Node& node, Scope& scope) {
    const std::string& name = required(node, "name");
    if (args_.count(name)) return;
    const std::string* fallback = node.attribute("default");
    if (!fallback) {
      fail(node.where, "argument '" + name + "' has no default and no value was given",
           "robot.args." + name + " in the rig");
    }
    args_[name] = text_of(*fallback, scope, node.where);
  }

  void define_macro(const xml::Node& node, Scope& scope) {
    auto macro = std::make_shared<Macro>();
    macro->name = required(node, "name");
    if (macro->name.rfind(kPrefix, 0) == 0) macro->name = macro->name.substr(kPrefix.size());
    const std::string* params = node.attribute("params");
    macro->parameters = parse_parameters(params ? *params : "", node.where);
    macro->body = node;
    scope.macros[macro->name] = std::move(macro);
  }

  void insert_block(const xml::Node& node, Scope& scope, std::vector<xml::Node>& out) {
    const std::string name = text_of(required(node, "name"), scope, node.where);
    Property* property = scope.property(name);
    if (!property || !property->is_block) {
      fail(node.where, "no block named '" + name + "'",
           "a *" + name + " macro parameter or a block xacro:property");
    }
    const Nesting level(*this, node.where, "block '" + name + "'");
    if (property->block_expanded) {
      for (const xml::Node& copied : property->block) produced(copied);
      out.insert(out.end(), property->block.begin(), property->block.end());
      return;
    }
    const std::vector<xml::Node> block = property->block;  // copy: expansion may redefine it
    for (const xml::Node& inserted : block) expand_node(inserted, scope, out);
  }

  void element(const xml::Node& node, Scope& scope, std::vector<xml::Node>& out) {
    xml::Node made;
    made.name = text_of(required(node, "xacro:name"), scope, node.where);
    made.where = node.where;
    for (const auto& [key, value] : node.attributes) {
      if (key != "xacro:name") made.attributes.emplace_back(key, text_of(value, scope, node.where));
    }
    expand_children(node, scope, made.children);
    nodes_ += 1;
    produced_count_check(made.where);
    out.push_back(std::move(made));
  }

  void call_macro(const xml::Node& node, const std::string& name, Scope& caller,
                  std::vector<xml::Node>& out) {
    const std::shared_ptr<const Macro> macro = caller.macro(name);
    if (!macro) {
      fail(node.where, "<" + node.name + "> is neither a xacro keyword nor a defined macro",
           "a macro defined (or included) before this line, or one of include, property, arg, "
           "macro, if, unless, insert_block, element");
    }
    const Nesting level(*this, node.where, "macro '" + name + "'");
    expanded_once_more(node.where, "macro calls");
    Scope local;
    local.parent = &caller;
    std::vector<const xml::Node*> blocks;
    for (const xml::Node& child : node.children) {
      if (child.kind == xml::Node::Kind::element) blocks.push_back(&child);
    }
    std::size_t next_block = 0;
    for (const auto& [key, value] : node.attributes) {
      bool known = false;
      for (const Parameter& p : macro->parameters) known = known || p.name == key;
      if (!known) {
        fail(node.where, "macro '" + name + "' has no parameter '" + key + "'",
             "one of its params: " + required(macro->body, "params"));
      }
    }
    for (const Parameter& p : macro->parameters) {
      Property property;
      property.defined_in = &local;
      property.where = node.where;
      if (p.kind != Parameter::Kind::plain) {
        if (next_block >= blocks.size()) {
          fail(node.where, "macro '" + name + "' needs the block parameter '" + p.name + "'",
               "one more child element of <" + node.name + ">");
        }
        // Expanded now, in the caller's scope, as xacro does: a block that is itself an
        // insert_block of the caller's block then means the caller's, not this macro's.
        const xml::Node& block = *blocks[next_block++];
        property.is_block = true;
        property.block_expanded = true;
        if (p.kind == Parameter::Kind::block) {
          expand_node(block, caller, property.block);
        } else {
          for (const xml::Node& c : block.children) {
            if (c.kind == xml::Node::Kind::element) expand_node(c, caller, property.block);
          }
        }
      } else if (const std::string* given = node.attribute(p.name)) {
        const Value value = evaluate_text(*given, caller, node.where);
        property.value = value.kind == Value::Kind::text ? xacro::parse_literal(value.text) : value;
      } else if (p.from_caller && caller.property(p.name)) {
        property.value = resolve(p.name, *caller.property(p.name), node.where);
      } else if (p.default_text) {
        const Value value = evaluate_text(*p.default_text, local, macro->body.where);
        property.value = value.kind == Value::Kind::text ? xacro::parse_literal(value.text) : value;
      } else {
        fail(node.where, "macro '" + name + "' needs the parameter '" + p.name + "'",
             p.name + "=\"...\" on <" + node.name + ">");
      }
      local.properties[p.name] = std::move(property);
    }
    expand_children(macro->body, local, out);
  }

  void produced_count_check(const model::SourceLocation& where) const {
    if (nodes_ > kMaxNodes) {
      fail(where,
           "the expansion produces more than " + std::to_string(kMaxNodes) +
               " elements (macros or blocks that multiply?)",
           "a description that expands to fewer elements");
    }
  }

  const XacroInput& input_;
  std::map<std::string, std::string> args_;
  std::map<std::string, xml::Node> parsed_;  // canonical path -> parsed file
  std::vector<std::string> include_stack_;
  int depth_ = 0;
  std::size_t nodes_ = 0;
  std::size_t expansions_ = 0;
  std::size_t includes_ = 0;
  std::size_t text_bytes_ = 0;
};

}  // namespace

xml::Node expand_xacro(const XacroInput& input) {
  return Expander(input).run();
}

}  // namespace rigdesign::io
