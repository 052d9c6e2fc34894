// Issue 37 item 4: a rig file written back after an edit by hand changes only the characters of
// the values edited. Every expected text below is written out by hand from the input text.
#include "rigdesign/io/config/rig_text_editor.hpp"

#include <catch2/catch.hpp>

#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/model/input_error.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;

namespace {

// Flow-style and block-style poses, comments (one with a two-byte character), quoted names.
const std::string kEditorRig = R"(# Test rig — comments and formatting must survive (°, UTF-8).
name: Editor test
body:
  radius: 0.2
  height: 0.4
distance_of_interest: 2.0
mounts:
  - id: front   # the front camera
    sensor: orbbec_astra
    mode: "qvga_30"
    pose: {xyz: [0.20, 0, 0.3], rpy_deg: [0, 10, 0]}   # pitched down
  - id: rear
    sensor: velodyne_vlp16
    mode: vlp16_10hz
    pose:
      xyz:
        - -0.2    # behind the centre
        - 0.0
        - 0.45
      rpy_deg: [0, 0, 180]
)";

std::string with_replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("rig text editor: only the edited values change", "[io][editor]") {
  io::MountEdit front;
  front.mount_id = "front";
  front.xyz = {0.25, 0.0, 0.35};
  front.rpy_deg = {0.0, 12.5, -3.0};
  io::MountEdit rear;
  rear.mount_id = "rear";
  rear.xyz = {-0.25, 0.0, 0.45};
  rear.mode = "vlp16_20hz";
  const std::vector<io::MountEdit> edits = {front, rear};
  std::string expected =
      with_replaced(kEditorRig, "pose: {xyz: [0.20, 0, 0.3], rpy_deg: [0, 10, 0]}",
                    "pose: {xyz: [0.25, 0, 0.35], rpy_deg: [0, 12.5, -3]}");
  expected = with_replaced(expected, "        - -0.2    # behind", "        - -0.25    # behind");
  expected = with_replaced(expected, "        - 0.0\n", "        - 0\n");
  expected = with_replaced(expected, "mode: vlp16_10hz", "mode: vlp16_20hz");
  CHECK(io::edit_rig_text(kEditorRig, "test.yaml", edits) == expected);
}

TEST_CASE("rig text editor: a quoted name stays quoted, a hostile one is escaped", "[io][editor]") {
  io::MountEdit edit;
  edit.mount_id = "front";
  edit.mode = "vga_30";
  const std::vector<io::MountEdit> one = {edit};
  CHECK(io::edit_rig_text(kEditorRig, "t.yaml", one) ==
        with_replaced(kEditorRig, "mode: \"qvga_30\"", "mode: \"vga_30\""));
  edit.mode.reset();
  edit.sensor = "a: b # c";
  const std::vector<io::MountEdit> hostile = {edit};
  CHECK(io::edit_rig_text(kEditorRig, "t.yaml", hostile) ==
        with_replaced(kEditorRig, "sensor: orbbec_astra", "sensor: \"a: b # c\""));
  // Single quotes, with YAML's doubled quote inside, stay single quotes.
  const std::string single = with_replaced(kEditorRig, "mode: \"qvga_30\"", "mode: 'it''s'   # q");
  edit.sensor.reset();
  edit.mode = "o'k";
  const std::vector<io::MountEdit> quoted = {edit};
  CHECK(io::edit_rig_text(single, "t.yaml", quoted) ==
        with_replaced(single, "mode: 'it''s'   # q", "mode: 'o''k'   # q"));
}

TEST_CASE("rig text editor: refusals name the file, line and column", "[io][editor]") {
  io::MountEdit edit;
  edit.mount_id = "side";
  edit.xyz = {0, 0, 0};
  const std::vector<io::MountEdit> missing = {edit};
  try {
    io::edit_rig_text(kEditorRig, "rig.yaml", missing);
    FAIL("no error");
  } catch (const model::InputError& error) {
    CHECK(error.diagnostics().front().message().find("rig.yaml:8:") == 0);  // the mounts list
    CHECK(error.diagnostics().front().message().find("no mount 'side'") != std::string::npos);
  }
}

TEST_CASE("saving edits: atomic, and refused when the file changed on disk", "[io][editor]") {
  test::TempFolder folder;
  const std::string path = folder.write("rig.yaml", kEditorRig);
  io::MountEdit edit;
  edit.mount_id = "front";
  edit.rpy_deg = {0, 20, 0};
  const std::vector<io::MountEdit> edits = {edit};
  const std::string written = io::save_rig_edits(path, kEditorRig, edits);
  CHECK(test::file_text(path) == written);
  CHECK(written == with_replaced(kEditorRig, "rpy_deg: [0, 10, 0]", "rpy_deg: [0, 20, 0]"));
  CHECK(folder.entries() == 1);  // no temporary left behind
  // The file on disk is now `written`; a save from the stale text must not overwrite it.
  CHECK_THROWS_AS(io::save_rig_edits(path, kEditorRig, edits), model::InputError);
  CHECK(test::file_text(path) == written);
}

TEST_CASE("rig text editor: a mount without the edited key or not a map is refused (fuzz)",
          "[io][editor]") {
  // Found by fuzz/targets/rig_text_edit.cpp: indexing a missing key threw yaml-cpp's
  // InvalidNode instead of the project's InputError.
  io::MountEdit edit;
  edit.mount_id = "front";
  edit.mode = "m";
  const std::vector<io::MountEdit> edits = {edit};
  const std::string no_mode = "mounts:\n  - id: front\n    sensor: s\n  - just a scalar\n";
  try {
    io::edit_rig_text(no_mode, "f.yaml", edits);
    FAIL("no error");
  } catch (const model::InputError& error) {
    CHECK(error.diagnostics().front().field == "mounts[0].mode");
  }
  CHECK_THROWS_AS(io::edit_rig_text("- a\n- b\n", "f.yaml", edits), model::InputError);
  CHECK_THROWS_AS(io::edit_rig_text("mounts: [1, {id: front}]\n", "f.yaml", edits),
                  model::InputError);
}

TEST_CASE("rig text editor: CR LF lines are edited in place, a lone CR or a folded quote refused",
          "[io][editor]") {
  io::MountEdit edit;
  edit.mount_id = "front";
  edit.mode = "vga_30";
  edit.xyz = {1, 2, 3};
  const std::vector<io::MountEdit> edits = {edit};
  // Windows line ends: the same edit, the CR LF pairs kept.
  const std::string crlf =
      "mounts:\r\n  - id: front\r\n    mode: 'qvga_30'\r\n"
      "    pose: {xyz: [0, 0, 0.5], rpy_deg: [0, 0, 0]}\r\n";
  CHECK(io::edit_rig_text(crlf, "f.yaml", edits) ==
        "mounts:\r\n  - id: front\r\n    mode: 'vga_30'\r\n"
        "    pose: {xyz: [1, 2, 3], rpy_deg: [0, 0, 0]}\r\n");
  // A carriage return alone breaks a line for the parser but not for the offsets: refused at
  // its line (the third: two line feeds before it).
  const std::string lone_cr = "mounts:\n  - id: front\n    mode: qvga_30\r    pose: {}\n";
  try {
    io::edit_rig_text(lone_cr, "f.yaml", edits);
    FAIL("no error");
  } catch (const model::InputError& error) {
    CHECK(error.diagnostics().front().message().find("f.yaml:3:18:") == 0);
  }
  // A double-quoted mode folded over two lines: its characters are not its value.
  const std::string folded = "mounts:\n  - id: front\n    mode: \"qvga\n      _30\"\n";
  edit.xyz.reset();
  const std::vector<io::MountEdit> mode_only = {edit};
  CHECK_THROWS_AS(io::edit_rig_text(folded, "f.yaml", mode_only), model::InputError);
}

TEST_CASE("rig text editor: a pose from urdf_link edited becomes numbers, in the map's own style",
          "[io][editor]") {
  io::MountEdit edit;
  edit.mount_id = "front";
  edit.xyz = {0.1, 0, 0.25};
  edit.rpy_deg = {0, 5, 0};
  const std::vector<io::MountEdit> edits = {edit};
  // Flow map: the whole map replaced, the link's `frame` going with it.
  const std::string flow =
      with_replaced(kEditorRig, "pose: {xyz: [0.20, 0, 0.3], rpy_deg: [0, 10, 0]}",
                    "pose: {urdf_link: oakd_rgb_camera_frame, frame: optical}");
  CHECK(io::edit_rig_text(flow, "rig.yaml", edits) ==
        with_replaced(flow, "{urdf_link: oakd_rgb_camera_frame, frame: optical}",
                      "{xyz: [0.1, 0, 0.25], rpy_deg: [0, 5, 0]}"));
  // Block map: its lines replaced by two at the same indentation; the comment after kept.
  const std::string block = with_replaced(
      kEditorRig, "    pose: {xyz: [0.20, 0, 0.3], rpy_deg: [0, 10, 0]}   # pitched down\n",
      "    pose:\n      urdf_link: camera_link\n      frame: body\n    # next\n");
  CHECK(io::edit_rig_text(block, "rig.yaml", edits) ==
        with_replaced(block, "      urdf_link: camera_link\n      frame: body\n",
                      "      xyz: [0.1, 0, 0.25]\n      rpy_deg: [0, 5, 0]\n"));
  // Both triples are needed to replace a link.
  edit.rpy_deg.reset();
  const std::vector<io::MountEdit> xyz_only = {edit};
  CHECK_THROWS_AS(io::edit_rig_text(flow, "rig.yaml", xyz_only), model::InputError);
}

TEST_CASE("rig text editor: mounts removed lose their lines, added ones follow the last",
          "[io][editor]") {
  io::MountEdit removed;
  removed.kind = io::MountEdit::Kind::remove;
  removed.mount_id = "rear";
  io::MountEdit added;
  added.kind = io::MountEdit::Kind::add;
  added.mount_id = "side cam";
  added.sensor = "orbbec_astra";
  added.mode = "qvga_30";
  added.xyz = {0, 0.2, 0.3};
  added.rpy_deg = {0, 0, 90};
  // The rear mount is the last: its seven lines (comment inside) go, the new mount takes the
  // front's indentation, its id quoted (it has a blank).
  const std::vector<io::MountEdit> both = {removed, added};
  const std::size_t rear = kEditorRig.find("  - id: rear");
  const std::string expected =
      kEditorRig.substr(0, rear) +
      "  - {id: \"side cam\", sensor: orbbec_astra, mode: qvga_30, pose: {xyz: [0, 0.2, 0.3], "
      "rpy_deg: [0, 0, 90]}}\n";
  CHECK(io::edit_rig_text(kEditorRig, "rig.yaml", both) == expected);
  // Removing the first mount leaves the rear one as it was written.
  removed.mount_id = "front";
  const std::vector<io::MountEdit> first = {removed};
  const std::size_t front = kEditorRig.find("  - id: front");
  CHECK(io::edit_rig_text(kEditorRig, "rig.yaml", first) ==
        kEditorRig.substr(0, front) + kEditorRig.substr(rear));
  // A file that ends without a line break after its last mount: the new one starts a line.
  const std::vector<io::MountEdit> add_only = {added};
  std::string unterminated = kEditorRig;
  unterminated.pop_back();
  CHECK(io::edit_rig_text(unterminated, "rig.yaml", add_only) ==
        unterminated +
            "\n  - {id: \"side cam\", sensor: orbbec_astra, mode: qvga_30, pose: {xyz: [0, 0.2, "
            "0.3], rpy_deg: [0, 0, 90]}}\n");
  // An id already taken is refused.
  added.mount_id = "front";
  const std::vector<io::MountEdit> taken = {added};
  CHECK_THROWS_AS(io::edit_rig_text(kEditorRig, "rig.yaml", taken), model::InputError);
}

namespace {

// Three mounts, the third's pose an alias of the first's (issue 53, reproducer 21), and the
// place of each anchor and alias counted by hand: line 4 is `  - {id: front, ...`.
const std::string kAliasRig =
    "name: aliases\n"
    "distance_of_interest: 3.0\n"
    "mounts:\n"
    "  - {id: front, sensor: s, mode: &md m5, pose: &fp {xyz: [0.5, 0, 0.4], rpy_deg: [0, 0, 0]}}\n"
    "  - {id: rear, sensor: s, mode: m5, pose: {xyz: [-0.5, 0, 0.2], rpy_deg: [0, 0, 180]}}\n"
    "  - {id: third, sensor: s, mode: *md, pose: *fp}\n";

// "rig.yaml:LINE:COLUMN:" of the first `marker` in `text`, both 1-based, counted here.
std::string place_of(const std::string& text, const std::string& marker) {
  const std::size_t at = text.find(marker);
  REQUIRE(at != std::string::npos);
  const std::size_t line_start = text.rfind('\n', at) + 1;
  return "rig.yaml:" + std::to_string(test::line_of(text, marker)) + ":" +
         std::to_string(at - line_start + 1) + ":";
}

std::string refusal(const std::string& text, const std::vector<io::MountEdit>& edits) {
  try {
    io::edit_rig_text(text, "rig.yaml", edits);
  } catch (const model::InputError& error) {
    return error.diagnostics().front().message();
  }
  return "(not refused)";
}

io::MountEdit moved(const std::string& id) {
  io::MountEdit edit;
  edit.mount_id = id;
  edit.xyz = {0.5, 0, 0.45};
  return edit;
}

}  // namespace

TEST_CASE("rig text editor: a value shared through an anchor or alias is refused at its place",
          "[io][editor]") {
  // The alias moved: refused at `*fp` (third's own line), not silently at front's anchor.
  const std::string third = refusal(kAliasRig, {moved("third")});
  CHECK(third.find(place_of(kAliasRig, "*fp")) == 0);
  CHECK(third.find("alias *fp") != std::string::npos);
  // The anchored value moved: refused at `&fp`, since third would move with it.
  const std::string front = refusal(kAliasRig, {moved("front")});
  CHECK(front.find(place_of(kAliasRig, "&fp")) == 0);
  CHECK(front.find("anchor &fp") != std::string::npos);
  // A scalar alias too: third's mode is front's.
  io::MountEdit mode;
  mode.mount_id = "third";
  mode.mode = "m10";
  CHECK(refusal(kAliasRig, {mode}).find(place_of(kAliasRig, "*md")) == 0);
  // Removing front would take the anchors third uses with it.
  io::MountEdit removed;
  removed.kind = io::MountEdit::Kind::remove;
  removed.mount_id = "front";
  CHECK(refusal(kAliasRig, {removed}).find(place_of(kAliasRig, "&md")) == 0);
  // A mount that shares nothing is edited as before, every other byte kept; removing the one
  // holding the aliases leaves the anchors' mount as written.
  const std::vector<io::MountEdit> rear = {moved("rear")};
  CHECK(io::edit_rig_text(kAliasRig, "rig.yaml", rear) ==
        with_replaced(kAliasRig, "xyz: [-0.5, 0, 0.2]", "xyz: [0.5, 0, 0.45]"));
  removed.mount_id = "third";
  const std::vector<io::MountEdit> third_removed = {removed};
  CHECK(io::edit_rig_text(kAliasRig, "rig.yaml", third_removed) ==
        with_replaced(kAliasRig, "  - {id: third, sensor: s, mode: *md, pose: *fp}\n", ""));
}

TEST_CASE("rig text editor: a merge key, a tag or a block scalar on the way is refused",
          "[io][editor]") {
  // A merge key in the mount: its keys may come from the merged map.
  const std::string merged =
      "base: &b {sensor: s, mode: m5}\nname: r\nmounts:\n"
      "  - id: front\n    <<: *b\n    pose: {xyz: [0.5, 0, 0.4], rpy_deg: [0, 0, 0]}\n";
  const std::string merge_refusal = refusal(merged, {moved("front")});
  CHECK(merge_refusal.find(place_of(merged, "<<")) == 0);
  CHECK(merge_refusal.find("merge") != std::string::npos);
  // A tagged number: its text is `!!float 0.4`, not 0.4.
  const std::string tagged = with_replaced(kEditorRig, "0.45", "!!float 0.45");
  io::MountEdit rear = moved("rear");
  const std::string tag_refusal = refusal(tagged, {rear});
  CHECK(tag_refusal.find(place_of(tagged, "!!float")) == 0);
  CHECK(tag_refusal.find("tag") != std::string::npos);
  // A mode written as a block scalar spans lines.
  const std::string block = with_replaced(kEditorRig, "mode: vlp16_10hz", "mode: |\n      vlp16");
  io::MountEdit mode;
  mode.mount_id = "rear";
  mode.mode = "vlp16_20hz";
  CHECK(refusal(block, {mode}).find(place_of(block, "|")) == 0);
  // A plain scalar folded over two lines reads "vlp16 10hz": not one token.
  const std::string folded =
      with_replaced(kEditorRig, "mode: vlp16_10hz", "mode: vlp16\n      10hz");
  CHECK(refusal(folded, {mode}).find(place_of(folded, "vlp16\n      10hz")) == 0);
}

TEST_CASE("rig text editor: a mount is not added after a last item that is an alias (fuzz)",
          "[io][editor]") {
  // Found by fuzz/targets/rig_text_edit.cpp: the alias `*whole` has its anchor's mark, so the
  // new mount landed between the anchored item and the alias.
  const std::string text =
      "name: a\nmounts:\n  - &whole\n    id: rear\n    sensor: s\n    mode: m\n"
      "    pose: {xyz: [0, 0, 1], rpy_deg: [0, 0, 0]}\n  - *whole\n";
  io::MountEdit added;
  added.kind = io::MountEdit::Kind::add;
  added.mount_id = "side";
  added.sensor = "s";
  added.mode = "m";
  added.xyz = {0, 0.2, 0.3};
  added.rpy_deg = {0, 0, 90};
  CHECK(refusal(text, {added}).find(place_of(text, "*whole")) == 0);
}

TEST_CASE("rig text editor: a flow item over lines ends at its bracket (fuzz)", "[io][editor]") {
  // Found by fuzz/targets/rig_text_edit.cpp: the second line of b's flow map is less indented
  // than its dash, so the item was taken to end on its first line and the new mount split it.
  const std::string kept =
      "  - {id: b, sensor: s, mode: m\n,   pose: {xyz: [1, 0, 1], rpy_deg: [0, 0, 0]}}\n";
  const std::string text =
      "mounts:\n  - {id: a, sensor: s, mode: m, pose: {xyz: [0, 0, 1], rpy_deg: [0, 0, 0]}}\n" +
      kept;
  io::MountEdit removed;
  removed.kind = io::MountEdit::Kind::remove;
  removed.mount_id = "a";
  io::MountEdit added;
  added.kind = io::MountEdit::Kind::add;
  added.mount_id = "c";
  added.sensor = "s";
  added.mode = "m";
  added.xyz = {0, 0.2, 0.3};
  added.rpy_deg = {0, 0, 90};
  const std::vector<io::MountEdit> edits = {removed, added};
  CHECK(io::edit_rig_text(text, "rig.yaml", edits) ==
        "mounts:\n" + kept +
            "  - {id: c, sensor: s, mode: m, pose: {xyz: [0, 0.2, 0.3], rpy_deg: [0, 0, 90]}}\n");
}
