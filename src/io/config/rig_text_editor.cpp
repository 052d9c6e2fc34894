// Edits a rig file's values in place: the parser says where each value starts; its token is
// scanned from there and only that token is replaced.
#include "rigdesign/io/config/rig_text_editor.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <string_view>
#include <vector>

#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/io/config/yaml_reader.hpp"
#include "rigdesign/io/file_bytes.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"
#include "yaml_text_spans.hpp"

namespace rigdesign::io {
namespace {

struct Replacement {
  std::size_t begin = 0;  // byte offset of the token's first character
  std::size_t end = 0;    // one past its last
  std::string text;
};

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
  const std::size_t begin = yaml_text::offset_of(text, mark.line, mark.column);
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
    // A quoted value on one line without escapes must read back as the parser's value; one
    // that folds over lines or escapes is not edited (its characters are not its value's).
    const std::string_view inner(text.data() + begin + 1, end > begin + 1 ? end - begin - 2 : 0);
    const bool escapes = inner.find(quote == '"' ? "\\" : "''") != std::string_view::npos;
    if (inner.find_first_of("\n\r") != std::string_view::npos || end - begin < 2 ||
        text[end - 1] != quote || (!escapes && inner != node.Scalar()))
      refuse(node, path, field, "could not be located in the file's text",
             "a plain scalar, or a quoted one on one line");
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

std::string triple_text(const std::array<double, 3>& values) {
  return "[" + model::exact_number(values[0]) + ", " + model::exact_number(values[1]) + ", " +
         model::exact_number(values[2]) + "]";
}

std::size_t offset_of_node(const std::string& text, const YAML::Node& node) {
  return yaml_text::offset_of(text, node.Mark().line, node.Mark().column);
}

// A pose given by a description's link, written as numbers: the whole pose value replaced
// (a flow map up to its brace, a block map over its lines), any `frame` going with the link.
Replacement pose_as_numbers(const std::string& text, const std::string& path,
                            const YAML::Node& pose, const MountEdit& edit,
                            const std::string& field) {
  if (!edit.xyz || !edit.rpy_deg)
    refuse(pose, path, field, "comes from urdf_link: an edit must give both xyz and rpy_deg",
           "xyz and rpy_deg together");
  const std::size_t begin = offset_of_node(text, pose);
  const std::string xyz = "xyz: " + triple_text(*edit.xyz);
  const std::string rpy = "rpy_deg: " + triple_text(*edit.rpy_deg);
  const std::string housing = edit.housing.empty() ? "" : "housing: " + name_text(edit.housing, 0);
  if (begin < text.size() && text[begin] == '{') {
    const std::size_t end = yaml_text::flow_end(text, begin);
    if (end == std::string::npos)
      refuse(pose, path, field, "could not be located in the file's text", "a map");
    return {begin, end, "{" + xyz + ", " + rpy + (housing.empty() ? "" : ", " + housing) + "}"};
  }
  const auto column = static_cast<std::size_t>(pose.Mark().column);
  if (begin - yaml_text::line_begin(text, begin) != column ||
      text.compare(yaml_text::line_begin(text, begin), column, std::string(column, ' ')) != 0)
    refuse(pose, path, field, "could not be located in the file's text",
           "a block map, its keys on lines of their own");
  const std::size_t end = yaml_text::block_content_end(text, begin, column);
  const std::string next_line =
      std::string(yaml_text::line_break_at(text, begin)) + std::string(column, ' ');
  return {begin, end, xyz + next_line + rpy + (housing.empty() ? "" : next_line + housing)};
}

// The lines of the block sequence item `item` (from its dash to its last content line and
// that line's break), or a refusal when the item shares a line with anything else.
Replacement item_lines(const std::string& text, const std::string& path, const YAML::Node& item,
                       const std::string& field) {
  const std::size_t mark = offset_of_node(text, item);
  const std::size_t line = yaml_text::line_begin(text, mark);
  const std::size_t dash = text.find_first_not_of(' ', line);
  if (dash >= mark || text[dash] != '-' || text.find_first_not_of(' ', dash + 1) != mark)
    refuse(item, path, field, "could not be located in the file's text",
           "a list item on lines of its own (`- ...`)");
  const std::size_t end = yaml_text::block_content_end(text, mark, dash - line + 1);
  const std::size_t after = std::min(
      text.size(), yaml_text::line_end(text, end) + yaml_text::line_break_at(text, end).size());
  return {line, after, {}};
}

std::string new_item_text(const MountEdit& edit) {
  return "{id: " + name_text(edit.mount_id, '\0') + ", sensor: " + name_text(*edit.sensor, '\0') +
         ", mode: " + name_text(*edit.mode, '\0') + ", pose: {xyz: " + triple_text(*edit.xyz) +
         ", rpy_deg: " + triple_text(*edit.rpy_deg) + "}}";
}

// Changes of a mount's sensor, mode and pose.
void change_mount(const std::string& text, const std::string& path, const YAML::Node& mount,
                  const MountEdit& edit, const std::string& field,
                  std::vector<Replacement>& replacements) {
  for (const auto& [key, value] :
       {std::pair{"sensor", edit.sensor}, std::pair{"mode", edit.mode}}) {
    if (!value) continue;
    Replacement r = token_of(text, mount[key], path, field + "." + key);
    r.text = name_text(*value, text[r.begin]);
    replacements.push_back(std::move(r));
  }
  if (!edit.xyz && !edit.rpy_deg) return;
  const YAML::Node pose = mount["pose"];
  if (!pose.IsDefined() || !pose.IsMap())
    refuse(mount, path, field + ".pose", "is missing", "a map with xyz and rpy_deg");
  if (pose["urdf_link"].IsDefined()) {
    replacements.push_back(pose_as_numbers(text, path, pose, edit, field + ".pose"));
    return;
  }
  const YAML::Node frame = pose["frame"];
  if (frame.IsDefined() && !(frame.IsScalar() && frame.Scalar() == "body"))
    refuse(frame, path, field + ".pose.frame",
           "is not `body`: the edited numbers are the sensor frame's (x along the optical axis)",
           "frame: body, or no frame");
  if (edit.xyz) edit_triple(text, path, pose, "xyz", *edit.xyz, field + ".pose", replacements);
  if (edit.rpy_deg)
    edit_triple(text, path, pose, "rpy_deg", *edit.rpy_deg, field + ".pose", replacements);
}

YAML::Node mounts_of(const std::string& path, const YAML::Node& root) {
  if (!root.IsMap()) refuse(root, path, "file", "is not a map", "a rig file");
  const YAML::Node mounts = root["mounts"];
  if (!mounts.IsDefined() || !mounts.IsSequence())
    refuse(root, path, "mounts", "is missing or not a list", "the rig's mounts");
  return mounts;
}

std::optional<std::size_t> mount_index(const YAML::Node& mounts, const std::string& id) {
  std::optional<std::size_t> index;
  for (std::size_t i = 0; i < mounts.size(); ++i) {
    if (!mounts[i].IsMap()) continue;
    const YAML::Node node = mounts[i]["id"];
    if (node.IsDefined() && node.IsScalar() && node.Scalar() == id) index = i;
  }
  return index;
}

// The replacements for the changes and removals in `edits`; every node is checked for its
// kind before it is indexed.
std::vector<Replacement> replacements_of(const std::string& text, const std::string& path,
                                         const YAML::Node& root, std::span<const MountEdit> edits) {
  const YAML::Node mounts = mounts_of(path, root);
  std::vector<Replacement> replacements;
  for (const MountEdit& edit : edits) {
    if (edit.kind == MountEdit::Kind::add) continue;
    const std::optional<std::size_t> index = mount_index(mounts, edit.mount_id);
    if (!index)
      refuse(mounts, path, "mounts", "has no mount '" + edit.mount_id + "'",
             "an id of the rig's mounts");
    const std::string field = "mounts[" + std::to_string(*index) + "]";
    if (edit.kind == MountEdit::Kind::remove)
      replacements.push_back(item_lines(text, path, mounts[*index], field));
    else
      change_mount(text, path, mounts[*index], edit, field, replacements);
  }
  return replacements;
}

// The mounts added, appended after the list's last item at its dash's indentation.
std::vector<Replacement> additions_of(const std::string& text, const std::string& path,
                                      const YAML::Node& root, std::span<const MountEdit> edits) {
  std::vector<Replacement> additions;
  for (const MountEdit& edit : edits) {
    if (edit.kind != MountEdit::Kind::add) continue;
    const YAML::Node mounts = mounts_of(path, root);
    if (!edit.sensor || !edit.mode || !edit.xyz || !edit.rpy_deg)
      refuse(mounts, path, "mounts",
             "cannot take mount '" + edit.mount_id + "' without its sensor, mode and pose",
             "sensor, mode, xyz and rpy_deg");
    const bool added_twice = std::any_of(edits.data(), &edit, [&](const MountEdit& other) {
      return other.kind == MountEdit::Kind::add && other.mount_id == edit.mount_id;
    });
    if (mount_index(mounts, edit.mount_id) || added_twice)
      refuse(mounts, path, "mounts", "already has a mount '" + edit.mount_id + "'", "a new id");
    if (mounts.size() == 0)
      refuse(mounts, path, "mounts", "has no item to place a new mount after",
             "at least one mount in the file");
    const Replacement last = item_lines(text, path, mounts[mounts.size() - 1],
                                        "mounts[" + std::to_string(mounts.size() - 1) + "]");
    const std::size_t dash = text.find('-', last.begin);
    const std::string line_break(yaml_text::line_break_at(text, last.begin));
    // A file whose last mount has no line break after it gets one before the new mount.
    const bool unterminated = last.end == text.size() && !text.empty() && text.back() != '\n';
    additions.push_back({last.end, last.end,
                         (unterminated ? line_break : "") + std::string(dash - last.begin, ' ') +
                             "- " + new_item_text(edit) + line_break});
  }
  return additions;
}

std::string with_replacements(std::string text, std::vector<Replacement> replacements) {
  // From the end backwards, so earlier offsets stay valid.
  std::stable_sort(replacements.begin(), replacements.end(),
                   [](const Replacement& a, const Replacement& b) { return a.begin > b.begin; });
  for (const Replacement& r : replacements) text.replace(r.begin, r.end - r.begin, r.text);
  return text;
}

}  // namespace

std::string edit_rig_text(const std::string& text, const std::string& path,
                          std::span<const MountEdit> edits) {
  // yaml-cpp's marks count a lone carriage return as a line break; offset_of counts only line
  // feeds, so such a file's marks would land on the wrong bytes.
  for (std::size_t i = text.find('\r'); i != std::string::npos; i = text.find('\r', i + 1)) {
    if (i + 1 < text.size() && text[i + 1] == '\n') continue;
    const std::size_t line_start =
        text.rfind('\n', i) == std::string::npos ? 0 : text.rfind('\n', i) + 1;
    const auto before = text.begin() + static_cast<std::ptrdiff_t>(i);
    throw model::InputError(model::Diagnostic(
        {path, 1 + static_cast<int>(std::count(text.begin(), before, '\n')),
         1 + static_cast<int>(i - line_start)},
        "file", "has a carriage return that does not end a line", "lines ending in LF or CR LF"));
  }
  try {
    // Changes and removals first; additions on the text that results, after its last mount.
    const std::string changed =
        with_replacements(text, replacements_of(text, path, YAML::Load(text), edits));
    const std::vector<Replacement> additions =
        additions_of(changed, path, YAML::Load(changed), edits);
    if (additions.empty()) return changed;
    // Every addition has the same anchor (the last mount left); they go in the edits' order.
    std::string appended;
    for (const Replacement& r : additions) appended += r.text;
    std::string edited = changed;
    return edited.insert(additions.front().begin, appended);
  } catch (const YAML::Exception& error) {
    // Syntax errors, and a backstop for any node a check above did not foresee.
    throw model::InputError(model::Diagnostic({path, error.mark.line + 1, error.mark.column + 1},
                                              "file",
                                              "is not a rig the edit can apply to: " + error.msg));
  }
}

std::string save_rig_edits(const std::string& path, const std::string& loaded_text,
                           std::span<const MountEdit> edits) {
  if (read_file_bytes(path, "a rig file") != loaded_text) {
    throw model::InputError(model::Diagnostic(
        {path, 0, 0}, "file", "changed on disk since it was loaded; not overwritten",
        "reload the rig, then edit again"));
  }
  const std::string edited = edit_rig_text(loaded_text, path, edits);
  write_file_atomically(path, edited);
  return edited;
}

}  // namespace rigdesign::io
