// Fuzz target: the rig text editor behind `serve`'s save (io/config/rig_text_editor): any text
// with an edit of every value kind to the first mount (by the id after the first "id:") and to
// a mount "front", that mount's removal, and a mount added. The token and line scans must stay
// inside the text and refuse what they cannot place.
#include <algorithm>
#include <vector>

#include "fuzz_input.hpp"
#include "rigdesign/io/config/rig_text_editor.hpp"

namespace {

// The word after the first "id:", as a mount id to edit ("front" when there is none).
std::string first_id(const std::string& text) {
  const std::size_t at = text.find("id:");
  if (at == std::string::npos) return "front";
  std::size_t begin = text.find_first_not_of(' ', at + 3);
  if (begin == std::string::npos) return "front";
  const std::size_t end = text.find_first_of(" \n\r#,}", begin);
  return text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(rigdesign::fuzz::as_text(data, size));
  for (const std::string& id : {first_id(text), std::string("front")}) {
    rigdesign::io::MountEdit edit;
    edit.mount_id = id;
    edit.sensor = "sensor_\"quoted\"";
    edit.mode = "mode-1";
    edit.xyz = std::array<double, 3>{0.125, -1e-7, 3.0};
    edit.rpy_deg = std::array<double, 3>{-180.0, 0.5, 90.0};
    const std::vector<rigdesign::io::MountEdit> edits = {edit};
    rigdesign::fuzz::expect_input_errors(
        [&] { rigdesign::io::edit_rig_text(text, "rig.yaml", edits); });
    rigdesign::io::MountEdit removed;
    removed.kind = rigdesign::io::MountEdit::Kind::remove;
    removed.mount_id = id;
    rigdesign::io::MountEdit added = edit;
    added.kind = rigdesign::io::MountEdit::Kind::add;
    added.mount_id = "new mount";
    const std::vector<rigdesign::io::MountEdit> list_edits = {removed, added};
    rigdesign::fuzz::expect_input_errors(
        [&] { rigdesign::io::edit_rig_text(text, "rig.yaml", list_edits); });
  }
  return 0;
}
