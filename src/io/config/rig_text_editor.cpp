// Edits a rig file's values in place: the parser says where each value starts; its token is
// scanned from there and only that token is replaced.
#include "rigdesign/io/config/rig_text_editor.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <map>
#include <string_view>
#include <vector>

#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
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

model::SourceLocation location_at(const std::string& path, yaml_text::TextMark mark) {
  return {path, mark.first + 1, mark.second + 1};
}

std::string line_column(yaml_text::TextMark mark) {
  return std::to_string(mark.first + 1) + ":" + std::to_string(mark.second + 1);
}

// The rig file being edited: its text, its name in messages, and the values aliases share.
struct RigText {
  const std::string& text;
  const std::string& path;
  std::map<yaml_text::TextMark, yaml_text::SharedValue> shared;
};

// Refuses an edit that passes through `node` when its text is shared: the node carries an
// anchor some alias uses, or it is such an alias resolved (yaml-cpp gives both the anchor's
// mark). Its characters are written once, so replacing them would change every place that uses
// them: another mount would move without being edited. `within` is the edited mount's text:
// an alias there is named, else the anchor.
void refuse_shared(const RigText& rig, const YAML::Node& node, const std::string& field,
                   std::pair<std::size_t, std::size_t> within) {
  if (!node.IsDefined()) return;
  const auto found = rig.shared.find({node.Mark().line, node.Mark().column});
  if (found == rig.shared.end()) return;
  const yaml_text::SharedValue& value = found->second;
  const std::string expected = "the value written out in full where it is edited, without & or *";
  for (const yaml_text::TextMark& alias : value.alias_marks) {
    const std::size_t at = yaml_text::offset_of(rig.text, alias.first, alias.second);
    if (at >= within.first && at < within.second)
      throw model::InputError(
          model::Diagnostic(location_at(rig.path, alias), field,
                            "is the alias *" + value.anchor + " of the value anchored at " +
                                line_column(value.anchor_mark) +
                                ": editing it would change every place that uses that anchor",
                            expected));
  }
  throw model::InputError(model::Diagnostic(
      location_at(rig.path, value.anchor_mark), field,
      "carries the anchor &" + value.anchor + " that " + std::to_string(value.alias_marks.size()) +
          " alias(es) use (the first at " + line_column(value.alias_marks.front()) +
          "): editing it would change them too",
      expected));
}

// Refuses replacing text that holds an anchor an alias outside it uses: the alias would be left
// naming nothing, or the value it shares would change with the edit.
void refuse_anchors_within(const RigText& rig, std::size_t begin, std::size_t end,
                           const std::string& field) {
  for (const auto& [mark, value] : rig.shared) {
    const std::size_t anchor = yaml_text::offset_of(rig.text, mark.first, mark.second);
    if (anchor < begin || anchor >= end) continue;
    for (const yaml_text::TextMark& alias : value.alias_marks) {
      const std::size_t at = yaml_text::offset_of(rig.text, alias.first, alias.second);
      if (at >= begin && at < end) continue;
      throw model::InputError(model::Diagnostic(
          location_at(rig.path, mark), field,
          "holds the anchor &" + value.anchor + " that the alias at " + line_column(alias) +
              " uses: the edit would change or remove what that alias shares",
          "the value written out in full at the alias, without & or *"));
    }
  }
}

// Refuses an edit inside a map that merges another (`<<:`): a value may come from the merged
// map, and YAML readers that apply merges and those that do not would read the edit apart.
void refuse_merge(const std::string& path, const YAML::Node& map, const std::string& field) {
  if (!map.IsDefined() || !map.IsMap()) return;
  for (auto it = map.begin(); it != map.end(); ++it) {
    if (it->first.IsScalar() && it->first.Scalar() == "<<")
      refuse(it->first, path, field,
             "merges another map (`<<:`): its values may be written elsewhere and shared",
             "the keys written out in full, without a merge key");
  }
}

// One mount being edited: every node on the way to an edited value is checked against the
// file's anchors before its text is touched.
struct MountScope {
  const RigText& rig;
  std::pair<std::size_t, std::size_t> span;  // the mount's text: [begin, end) byte offsets
  std::string field;                         // "mounts[i]"

  // `node` (at `field` + `key`) when an edit may pass through it.
  YAML::Node checked(const YAML::Node& node, const std::string& key) const {
    refuse_shared(rig, node, field + key, span);
    refuse_merge(rig.path, node, field + key);
    return node;
  }
};

// The token of a scalar node: a quoted string up to its closing quote, or a plain scalar up to
// the end of its line, a flow delimiter or a comment, trailing blanks left out. Anything whose
// characters are not its value one to one is refused: a tag, a block scalar (| or >), a quoted
// or plain scalar folded over lines.
Replacement token_of(const MountScope& scope, const YAML::Node& node, const std::string& key) {
  const std::string& text = scope.rig.text;
  const std::string& path = scope.rig.path;
  const std::string field = scope.field + key;
  scope.checked(node, key);
  if (!node.IsDefined() || !node.IsScalar())
    refuse(node, path, field, "is missing or not a single value", "a number or a name");
  // yaml-cpp's tag of an untagged scalar: "?" plain, "!" quoted.
  if (node.Tag() != "?" && node.Tag() != "!")
    refuse(node, path, field,
           "has the tag " + node.Tag() + ": its text is not the value alone, so it is not edited",
           "a plain or quoted scalar without a tag");
  const YAML::Mark mark = node.Mark();
  const std::size_t begin = yaml_text::offset_of(text, mark.line, mark.column);
  std::size_t end = begin;
  const char quote = begin < text.size() ? text[begin] : '\0';
  if (quote == '|' || quote == '>')
    refuse(node, path, field, "is a block scalar (| or >): its text spans lines",
           "a plain scalar, or a quoted one on one line");
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
      refuse(node, path, field, "is a quoted scalar over several lines: its text is not its value",
             "a plain scalar, or a quoted one on one line");
  } else {
    while (end < text.size() && std::string_view(",]}\n\r").find(text[end]) == std::string::npos &&
           !(text[end] == '#' && end > begin && (text[end - 1] == ' ' || text[end - 1] == '\t')))
      ++end;
    while (end > begin && (text[end - 1] == ' ' || text[end - 1] == '\t')) --end;
    // The parser's value must be exactly these characters, or the mark was not where we think
    // (a plain scalar continued on the next line, an anchor before it).
    if (text.compare(begin, end - begin, node.Scalar()) != 0)
      refuse(node, path, field,
             "is not written as one token on its line (folded over lines, or with an anchor)",
             "a plain scalar on one line, or a quoted one");
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

void edit_triple(const MountScope& scope, const YAML::Node& pose, const char* key,
                 const std::array<double, 3>& values, std::vector<Replacement>& out) {
  const std::string field = std::string(".pose.") + key;
  const YAML::Node list = scope.checked(pose[key], field);
  if (!list.IsDefined() || !list.IsSequence() || list.size() != 3)
    refuse(pose, scope.rig.path, scope.field + field, "is missing or not a list of three numbers",
           std::string(key) + ": [a, b, c] to edit");
  for (std::size_t i = 0; i < 3; ++i) {
    Replacement r = token_of(scope, list[i], field + "[" + std::to_string(i) + "]");
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
Replacement pose_as_numbers(const MountScope& scope, const YAML::Node& pose,
                            const MountEdit& edit) {
  const std::string& text = scope.rig.text;
  const std::string& path = scope.rig.path;
  const std::string field = scope.field + ".pose";
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
  std::size_t end = yaml_text::block_content_end(text, mark, dash - line + 1);
  if (text[mark] == '{' || text[mark] == '[') {
    // A flow item may go on over lines less indented than its dash: it ends at its bracket,
    // with nothing but a comment after it on that line.
    const std::size_t close = yaml_text::flow_end(text, mark);
    if (close == std::string::npos || !yaml_text::blank_or_comment(std::string_view(text).substr(
                                          close, yaml_text::line_end(text, close) - close)))
      refuse(item, path, field, "could not be located in the file's text",
             "a list item on lines of its own (`- ...`)");
    end = std::max(end, yaml_text::line_end(text, close));
  }
  const std::size_t after = std::min(
      text.size(), yaml_text::line_end(text, end) + yaml_text::line_break_at(text, end).size());
  return {line, after, {}};
}

// The text a mount item spans, from its mark: a flow map to its brace, a block map over the
// lines indented at least as far as its first key. Only where an alias is looked for.
std::pair<std::size_t, std::size_t> item_span(const std::string& text, const YAML::Node& item) {
  const std::size_t begin = offset_of_node(text, item);
  if (begin < text.size() && text[begin] == '{') {
    const std::size_t end = yaml_text::flow_end(text, begin);
    return {begin, end == std::string::npos ? text.size() : end};
  }
  return {begin,
          yaml_text::block_content_end(text, begin, static_cast<std::size_t>(item.Mark().column))};
}

std::string new_item_text(const MountEdit& edit) {
  return "{id: " + name_text(edit.mount_id, '\0') + ", sensor: " + name_text(*edit.sensor, '\0') +
         ", mode: " + name_text(*edit.mode, '\0') + ", pose: {xyz: " + triple_text(*edit.xyz) +
         ", rpy_deg: " + triple_text(*edit.rpy_deg) + "}}";
}

// Changes of a mount's sensor, mode and pose.
void change_mount(const MountScope& scope, const YAML::Node& mount, const MountEdit& edit,
                  std::vector<Replacement>& replacements) {
  const std::string& path = scope.rig.path;
  for (const auto& [key, value] :
       {std::pair{"sensor", edit.sensor}, std::pair{"mode", edit.mode}}) {
    if (!value) continue;
    Replacement r = token_of(scope, mount[key], std::string(".") + key);
    r.text = name_text(*value, scope.rig.text[r.begin]);
    replacements.push_back(std::move(r));
  }
  if (!edit.xyz && !edit.rpy_deg) return;
  const YAML::Node pose = scope.checked(mount["pose"], ".pose");
  if (!pose.IsDefined() || !pose.IsMap())
    refuse(mount, path, scope.field + ".pose", "is missing", "a map with xyz and rpy_deg");
  if (pose["urdf_link"].IsDefined()) {
    // Every value of the map is replaced: none of them may be shared.
    for (auto it = pose.begin(); it != pose.end(); ++it)
      scope.checked(it->second, ".pose." + (it->first.IsScalar() ? it->first.Scalar() : "?"));
    replacements.push_back(pose_as_numbers(scope, pose, edit));
    return;
  }
  const YAML::Node frame = pose["frame"];
  if (frame.IsDefined() && !(frame.IsScalar() && frame.Scalar() == "body"))
    refuse(frame, path, scope.field + ".pose.frame",
           "is not `body`: the edited numbers are the sensor frame's (x along the optical axis)",
           "frame: body, or no frame");
  if (edit.xyz) edit_triple(scope, pose, "xyz", *edit.xyz, replacements);
  if (edit.rpy_deg) edit_triple(scope, pose, "rpy_deg", *edit.rpy_deg, replacements);
}

YAML::Node mounts_of(const RigText& rig, const YAML::Node& root) {
  if (!root.IsMap()) refuse(root, rig.path, "file", "is not a map", "a rig file");
  refuse_merge(rig.path, root, "file");
  const YAML::Node mounts = root["mounts"];
  if (!mounts.IsDefined() || !mounts.IsSequence())
    refuse(root, rig.path, "mounts", "is missing or not a list", "the rig's mounts");
  refuse_shared(rig, mounts, "mounts", {0, 0});
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
std::vector<Replacement> replacements_of(const RigText& rig, const YAML::Node& root,
                                         std::span<const MountEdit> edits) {
  const YAML::Node mounts = mounts_of(rig, root);
  std::vector<Replacement> replacements;
  for (const MountEdit& edit : edits) {
    if (edit.kind == MountEdit::Kind::add) continue;
    const std::optional<std::size_t> index = mount_index(mounts, edit.mount_id);
    if (!index)
      refuse(mounts, rig.path, "mounts", "has no mount '" + edit.mount_id + "'",
             "an id of the rig's mounts");
    const YAML::Node item = mounts[*index];
    const MountScope scope{rig, item_span(rig.text, item),
                           "mounts[" + std::to_string(*index) + "]"};
    scope.checked(item, "");
    const std::size_t first = replacements.size();
    if (edit.kind == MountEdit::Kind::remove)
      replacements.push_back(item_lines(rig.text, rig.path, item, scope.field));
    else
      change_mount(scope, item, edit, replacements);
    for (std::size_t i = first; i < replacements.size(); ++i)
      refuse_anchors_within(rig, replacements[i].begin, replacements[i].end, scope.field);
  }
  return replacements;
}

// The mounts added, appended after the list's last item at its dash's indentation.
std::vector<Replacement> additions_of(const RigText& rig, const YAML::Node& root,
                                      std::span<const MountEdit> edits) {
  const std::string& text = rig.text;
  std::vector<Replacement> additions;
  for (const MountEdit& edit : edits) {
    if (edit.kind != MountEdit::Kind::add) continue;
    const YAML::Node mounts = mounts_of(rig, root);
    if (!edit.sensor || !edit.mode || !edit.xyz || !edit.rpy_deg)
      refuse(mounts, rig.path, "mounts",
             "cannot take mount '" + edit.mount_id + "' without its sensor, mode and pose",
             "sensor, mode, xyz and rpy_deg");
    const bool added_twice = std::any_of(edits.data(), &edit, [&](const MountEdit& other) {
      return other.kind == MountEdit::Kind::add && other.mount_id == edit.mount_id;
    });
    if (mount_index(mounts, edit.mount_id) || added_twice)
      refuse(mounts, rig.path, "mounts", "already has a mount '" + edit.mount_id + "'", "a new id");
    if (mounts.size() == 0)
      refuse(mounts, rig.path, "mounts", "has no item to place a new mount after",
             "at least one mount in the file");
    const std::string last_field = "mounts[" + std::to_string(mounts.size() - 1) + "]";
    // An alias as the last item has its anchor's mark: the new mount would land there.
    refuse_shared(rig, mounts[mounts.size() - 1], last_field, {0, text.size()});
    const Replacement last = item_lines(text, rig.path, mounts[mounts.size() - 1], last_field);
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

// The list's lines are found by indentation and brackets; a scalar that runs on past them (a
// quote closed lines later) would make them wrong. The edited text must hold as many mounts as
// the edits leave, or nothing is written.
void require_list_kept(const std::string& path, const YAML::Node& root, const std::string& edited,
                       std::span<const MountEdit> edits) {
  const auto count = [&](MountEdit::Kind kind) {
    return std::count_if(edits.begin(), edits.end(),
                         [kind](const MountEdit& edit) { return edit.kind == kind; });
  };
  if (count(MountEdit::Kind::add) == 0 && count(MountEdit::Kind::remove) == 0) return;
  const YAML::Node mounts = root["mounts"];
  const YAML::Node after = YAML::Load(edited)["mounts"];
  const auto expected = static_cast<std::ptrdiff_t>(mounts.size()) + count(MountEdit::Kind::add) -
                        count(MountEdit::Kind::remove);
  if (!after.IsSequence() || static_cast<std::ptrdiff_t>(after.size()) != expected)
    refuse(mounts, path, "mounts",
           "could not be located in the file's text: an item's text runs past its lines",
           "list items whose values end on their own lines");
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
    const RigText rig{text, path, yaml_text::shared_values(text)};
    const YAML::Node root = YAML::Load(text);
    const std::string changed = with_replacements(text, replacements_of(rig, root, edits));
    const RigText changed_rig{changed, path, yaml_text::shared_values(changed)};
    const std::vector<Replacement> additions =
        additions_of(changed_rig, YAML::Load(changed), edits);
    // Every addition has the same anchor (the last mount left); they go in the edits' order.
    std::string appended;
    for (const Replacement& r : additions) appended += r.text;
    std::string edited = changed;
    if (!additions.empty()) edited.insert(additions.front().begin, appended);
    require_list_kept(path, root, edited, edits);
    return edited;
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
  // The rig loader's own rules, on the text about to be written: a saved rig always loads.
  load_rig_text(edited, path);
  replace_file_keeping_identity(path, edited);
  return edited;
}

}  // namespace rigdesign::io
