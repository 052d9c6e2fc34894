// Fuzz target: the rig text editor behind `serve`'s save (io/config/rig_text_editor): any text
// with an edit of every value kind to the first mount (by the id after the first "id:") and to
// a mount "front", that mount's removal, and a mount added. The token and line scans must stay
// inside the text and refuse what they cannot place. An edit that is not refused must touch
// only what it names (issue 53): the text it gives is read again and every other mount and
// top-level key must read exactly as before (a value shared through an anchor, an alias or a
// merge key would change with it: those are the editor's refusals), the edited values as given.
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <utility>
#include <vector>

#include "fuzz_input.hpp"
#include "rigdesign/io/config/rig_text_editor.hpp"

namespace {

using rigdesign::io::MountEdit;

// The word after the first "id:", as a mount id to edit ("front" when there is none).
std::string first_id(const std::string& text) {
  const std::size_t at = text.find("id:");
  if (at == std::string::npos) return "front";
  std::size_t begin = text.find_first_not_of(' ', at + 3);
  if (begin == std::string::npos) return "front";
  const std::size_t end = text.find_first_of(" \n\r#,}", begin);
  return text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

[[noreturn]] void finding(const char* what) {
  std::fprintf(stderr, "rig_text_edit: an accepted edit %s\n", what);
  std::abort();
}

void require(bool ok, const char* what) {
  if (!ok) finding(what);
}

// A node's whole content as text: equal for two nodes that read the same.
std::string dumped(const YAML::Node& node) {
  return YAML::Dump(node);
}

// The index the editor edits: the last mount whose id is `id`.
std::optional<std::size_t> index_of(const YAML::Node& mounts, const std::string& id) {
  std::optional<std::size_t> index;
  for (std::size_t i = 0; i < mounts.size(); ++i) {
    if (!mounts[i].IsMap()) continue;
    const YAML::Node node = mounts[i]["id"];
    if (node.IsDefined() && node.IsScalar() && node.Scalar() == id) index = i;
  }
  return index;
}

void require_triple(const YAML::Node& pose, const char* key, const std::array<double, 3>& want) {
  const YAML::Node list = pose[key];
  require(list.IsSequence() && list.size() == 3, "lost a pose triple");
  for (std::size_t i = 0; i < 3; ++i)
    require(list[i].IsScalar() && list[i].as<double>() == want[i],
            "wrote a number that reads back otherwise");
}

// Every top-level entry but `mounts` reads as before, in order (a key may be given twice).
void require_same_top(const YAML::Node& before, const YAML::Node& after) {
  require(before.size() == after.size(), "changed the top-level keys");
  for (auto old = before.begin(), now = after.begin(); old != before.end(); ++old, ++now) {
    require(dumped(old->first) == dumped(now->first), "changed a top-level key");
    if (old->first.IsScalar() && old->first.Scalar() == "mounts") continue;
    require(dumped(old->second) == dumped(now->second), "changed a top-level value");
  }
}

// The text before and after an accepted edit, parsed: the edited text must parse as a map
// whose top-level entries other than `mounts` read as before.
std::pair<YAML::Node, YAML::Node> parsed_edit(const std::string& text, const std::string& edited) {
  const YAML::Node before = YAML::Load(text);
  YAML::Node after;
  try {
    after = YAML::Load(edited);
  } catch (const YAML::Exception&) {
    finding("gave text that does not parse");
  }
  require(after.IsMap(), "gave a text that is no map");
  require_same_top(before, after);
  return {before, after};
}

// `edited` is `text` with `edit` (a change) applied: only that mount's edited values differ.
void check_change(const std::string& text, const std::string& edited, const MountEdit& edit) {
  const auto [before, after] = parsed_edit(text, edited);
  const YAML::Node old_mounts = before["mounts"];
  const YAML::Node new_mounts = after["mounts"];
  require(new_mounts.IsSequence() && new_mounts.size() == old_mounts.size(), "changed the list");
  const std::size_t index = *index_of(old_mounts, edit.mount_id);
  for (std::size_t i = 0; i < old_mounts.size(); ++i) {
    if (i != index) {
      require(dumped(new_mounts[i]) == dumped(old_mounts[i]), "changed another mount");
      continue;
    }
    const YAML::Node mount = new_mounts[i];
    require(mount.IsMap() && mount.size() == old_mounts[i].size(), "changed the mount's keys");
    for (auto old = old_mounts[i].begin(), now = mount.begin(); old != old_mounts[i].end();
         ++old, ++now) {
      require(dumped(old->first) == dumped(now->first), "changed a key of the mount");
      const std::string key = old->first.IsScalar() ? old->first.Scalar() : "";
      if (key == "sensor" || key == "mode" || key == "pose") continue;
      require(dumped(old->second) == dumped(now->second), "changed a value it was not given");
    }
    require(mount["sensor"].Scalar() == *edit.sensor, "wrote a sensor that reads otherwise");
    require(mount["mode"].Scalar() == *edit.mode, "wrote a mode that reads otherwise");
    require_triple(mount["pose"], "xyz", *edit.xyz);
    require_triple(mount["pose"], "rpy_deg", *edit.rpy_deg);
  }
}

// `edited` is `text` with mount `removed` taken out and `added` appended.
void check_list(const std::string& text, const std::string& edited, const std::string& removed,
                const MountEdit& added) {
  const auto [before, after] = parsed_edit(text, edited);
  const YAML::Node old_mounts = before["mounts"];
  const YAML::Node new_mounts = after["mounts"];
  require(new_mounts.IsSequence() && new_mounts.size() == old_mounts.size(), "lost or won mounts");
  const std::size_t gone = *index_of(old_mounts, removed);
  std::size_t next = 0;
  for (std::size_t i = 0; i < old_mounts.size(); ++i) {
    if (i == gone) continue;
    require(dumped(new_mounts[next++]) == dumped(old_mounts[i]), "changed a mount it kept");
  }
  const YAML::Node mount = new_mounts[next];
  require(mount["id"].Scalar() == added.mount_id, "wrote an id that reads otherwise");
  require_triple(mount["pose"], "xyz", *added.xyz);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(rigdesign::fuzz::as_text(data, size));
  for (const std::string& id : {first_id(text), std::string("front")}) {
    MountEdit edit;
    edit.mount_id = id;
    edit.sensor = "sensor_\"quoted\"";
    edit.mode = "mode-1";
    edit.xyz = std::array<double, 3>{0.125, -1e-7, 3.0};
    edit.rpy_deg = std::array<double, 3>{-180.0, 0.5, 90.0};
    const std::vector<MountEdit> edits = {edit};
    rigdesign::fuzz::expect_input_errors(
        [&] { check_change(text, rigdesign::io::edit_rig_text(text, "rig.yaml", edits), edit); });
    MountEdit removed;
    removed.kind = MountEdit::Kind::remove;
    removed.mount_id = id;
    MountEdit added = edit;
    added.kind = MountEdit::Kind::add;
    added.mount_id = "new mount";
    const std::vector<MountEdit> list_edits = {removed, added};
    rigdesign::fuzz::expect_input_errors([&] {
      check_list(text, rigdesign::io::edit_rig_text(text, "rig.yaml", list_edits), id, added);
    });
  }
  return 0;
}
