// Edits a rig file's values in place: the parser says where each value starts; its token is
// scanned from there and only that token is replaced.
#include "rigdesign/io/config/rig_text_editor.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"
#include "yaml_reader.hpp"

namespace rigdesign::io {
namespace {

struct Replacement {
  std::size_t begin = 0;  // byte offset of the token's first character
  std::size_t end = 0;    // one past its last
  std::string text;
};

// Byte offset of a 0-based line and column (yaml-cpp counts bytes: it passes UTF-8 through).
std::size_t offset_of(const std::string& text, int line, int column) {
  std::size_t offset = 0;
  for (int l = 0; l < line; ++l) {
    const std::size_t newline = text.find('\n', offset);
    if (newline == std::string::npos) return text.size();
    offset = newline + 1;
  }
  return std::min(text.size(), offset + static_cast<std::size_t>(column));
}

[[noreturn]] void refuse(const YAML::Node& node, const std::string& path, const std::string& field,
                         const std::string& problem, const std::string& expected) {
  throw model::InputError(model::Diagnostic(location_of(node, path), field, problem, expected));
}

// The token of a scalar node: a quoted string up to its closing quote, or a plain scalar up to
// the end of its line, a flow delimiter or a comment, trailing blanks left out.
Replacement token_of(const std::string& text, const YAML::Node& node, const std::string& path,
                     const std::string& field) {
  if (!node.IsDefined() || !node.IsScalar())
    refuse(node, path, field, "is missing or not a single value", "a number or a name");
  const YAML::Mark mark = node.Mark();
  const std::size_t begin = offset_of(text, mark.line, mark.column);
  std::size_t end = begin;
  const char quote = begin < text.size() ? text[begin] : '\0';
  if (quote == '"' || quote == '\'') {
    // Up to the closing quote: a backslash escapes in double quotes, '' is a quote in single.
    end = begin + 1;
    while (end < text.size()) {
      if (quote == '"' && text[end] == '\\') {
        end += 2;
      } else if (quote == '\'' && text[end] == '\'' && end + 1 < text.size() &&
                 text[end + 1] == '\'') {
        end += 2;
      } else if (text[end] == quote) {
        break;
      } else {
        ++end;
      }
    }
    end = std::min(text.size(), end + 1);
  } else {
    while (end < text.size() && std::string_view(",]}\n\r").find(text[end]) == std::string::npos &&
           !(text[end] == '#' && end > begin && (text[end - 1] == ' ' || text[end - 1] == '\t')))
      ++end;
    while (end > begin && (text[end - 1] == ' ' || text[end - 1] == '\t')) --end;
    // The parser's value must be exactly these characters, or the mark was not where we think.
    if (text.compare(begin, end - begin, node.Scalar()) != 0)
      refuse(node, path, field, "could not be located in the file's text",
             "a plain or quoted scalar");
  }
  return {begin, end, {}};
}

bool plain_name(const std::string& name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-' || c == '.';
  });
}

// A name in the quoting the file used (plain when it was plain and still can be).
std::string name_text(const std::string& name, char quote) {
  if (quote != '"' && quote != '\'' && plain_name(name)) return name;
  if (quote == '\'') {
    std::string quoted = "'";
    for (const char c : name) quoted += c == '\'' ? std::string("''") : std::string(1, c);
    return quoted + "'";
  }
  std::string quoted = "\"";
  for (const char c : name) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

void edit_triple(const std::string& text, const std::string& path, const YAML::Node& pose,
                 const char* key, const std::array<double, 3>& values, const std::string& field,
                 std::vector<Replacement>& out) {
  const YAML::Node list = pose[key];
  if (!list.IsDefined() || !list.IsSequence() || list.size() != 3)
    refuse(pose, path, field + "." + key, "is missing or not a list of three numbers",
           std::string(key) + ": [a, b, c] to edit");
  for (std::size_t i = 0; i < 3; ++i) {
    Replacement r =
        token_of(text, list[i], path, field + "." + key + "[" + std::to_string(i) + "]");
    r.text = model::exact_number(values[i]);
    out.push_back(std::move(r));
  }
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw model::InputError(
        model::Diagnostic({path, 0, 0}, "file", "cannot be read", "a rig file"));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The replacements for `edits`; every node is checked for its kind before it is indexed.
std::vector<Replacement> replacements_of(const std::string& text, const std::string& path,
                                         const YAML::Node& root, std::span<const MountEdit> edits) {
  if (!root.IsMap()) refuse(root, path, "file", "is not a map", "a rig file");
  const YAML::Node mounts = root["mounts"];
  if (!mounts.IsDefined() || !mounts.IsSequence())
    refuse(root, path, "mounts", "is missing or not a list", "the rig's mounts");
  std::vector<Replacement> replacements;
  for (const MountEdit& edit : edits) {
    std::optional<std::size_t> index;
    for (std::size_t i = 0; i < mounts.size(); ++i) {
      if (!mounts[i].IsMap()) continue;
      const YAML::Node id = mounts[i]["id"];
      if (id.IsDefined() && id.IsScalar() && id.Scalar() == edit.mount_id) index = i;
    }
    if (!index)
      refuse(mounts, path, "mounts", "has no mount '" + edit.mount_id + "'",
             "an id of the rig's mounts");
    const YAML::Node mount = mounts[*index];
    const std::string field = "mounts[" + std::to_string(*index) + "]";
    for (const auto& [key, value] :
         {std::pair{"sensor", edit.sensor}, std::pair{"mode", edit.mode}}) {
      if (!value) continue;
      Replacement r = token_of(text, mount[key], path, field + "." + key);
      r.text = name_text(*value, text[r.begin]);
      replacements.push_back(std::move(r));
    }
    if (!edit.xyz && !edit.rpy_deg) continue;
    const YAML::Node pose = mount["pose"];
    if (pose.IsDefined() && pose.IsMap() && pose["urdf_link"].IsDefined())
      refuse(pose, path, field + ".pose",
             "comes from urdf_link '" + pose["urdf_link"].as<std::string>("") +
                 "': the robot description places this mount",
             "move the link in the robot description, or give the mount xyz and rpy_deg");
    if (!pose.IsDefined() || !pose.IsMap())
      refuse(mount, path, field + ".pose", "is missing", "a map with xyz and rpy_deg");
    if (edit.xyz) edit_triple(text, path, pose, "xyz", *edit.xyz, field + ".pose", replacements);
    if (edit.rpy_deg)
      edit_triple(text, path, pose, "rpy_deg", *edit.rpy_deg, field + ".pose", replacements);
  }
  return replacements;
}

}  // namespace

std::string edit_rig_text(const std::string& text, const std::string& path,
                          std::span<const MountEdit> edits) {
  std::vector<Replacement> replacements;
  try {
    replacements = replacements_of(text, path, YAML::Load(text), edits);
  } catch (const YAML::Exception& error) {
    // Syntax errors, and a backstop for any node a check above did not foresee.
    throw model::InputError(model::Diagnostic({path, error.mark.line + 1, error.mark.column + 1},
                                              "file",
                                              "is not a rig the edit can apply to: " + error.msg));
  }
  // From the end backwards, so earlier offsets stay valid.
  std::sort(replacements.begin(), replacements.end(),
            [](const Replacement& a, const Replacement& b) { return a.begin > b.begin; });
  std::string edited = text;
  for (const Replacement& r : replacements) edited.replace(r.begin, r.end - r.begin, r.text);
  return edited;
}

std::string save_rig_edits(const std::string& path, const std::string& loaded_text,
                           std::span<const MountEdit> edits) {
  if (read_text(path) != loaded_text) {
    throw model::InputError(model::Diagnostic(
        {path, 0, 0}, "file", "changed on disk since it was loaded; not overwritten",
        "reload the rig, then edit again"));
  }
  const std::string edited = edit_rig_text(loaded_text, path, edits);
  write_file_atomically(path, edited);
  return edited;
}

}  // namespace rigdesign::io
