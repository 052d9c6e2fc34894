#pragma once
/// Writing a rig file back after an edit by hand (issue 37's studio): only the characters of
/// the values edited change; comments, key order, quoting and the formatting of every other
/// line stay byte for byte. Each edited value is located by the YAML parser's mark (line and
/// column) and replaced in the text; nothing is re-serialised.
#include <array>
#include <optional>
#include <span>
#include <string>

namespace rigdesign::io {

/// New values for one mount; unset fields stay as written. A mount added needs every field
/// (it is appended to the list in the style of the file's last mount); a mount removed loses
/// its lines. A pose given by urdf_link that is edited becomes xyz and rpy_deg (both needed).
struct MountEdit {
  enum class Kind { change, add, remove };
  Kind kind = Kind::change;
  std::string mount_id;
  std::optional<std::string> sensor;
  std::optional<std::string> mode;
  std::optional<std::array<double, 3>> xyz;      ///< [m]
  std::optional<std::array<double, 3>> rpy_deg;  ///< [deg]
  /// The housing a pose taken from urdf_link keeps when it is written as numbers (the
  /// description link's collision the sensor still sits in); empty: none.
  std::string housing;
};

/// `text` (the rig file read from `path`, which names it in errors) with `edits` applied.
/// Numbers are written as the shortest text that reads back exactly. Throws InputError at the
/// value's file:line:col when the file is not a rig the edit can apply to: no such mount, a
/// field the edit needs missing, or a list or pose written in a form it cannot place text in.
/// Refused too, so that an edit changes nothing but what it names: a value on the way to the
/// edited one that carries an anchor some alias uses, or is such an alias (its text is shared:
/// another mount would change with it), text replaced or removed that holds an anchor used
/// elsewhere, a map with a merge key (`<<:`), and a scalar whose characters are not its value
/// alone (a tag, a block scalar, a plain or quoted scalar folded over lines).
std::string edit_rig_text(const std::string& text, const std::string& path,
                          std::span<const MountEdit> edits);

/// Applies `edits` to the rig file at `path` and writes it with replace_file_keeping_identity
/// (mode, owner, group and hard links kept). `loaded_text` is the file as it was read when
/// editing began: if the file on disk differs now, nothing is written and InputError says so
/// (someone else changed it). The edited text is read by the rig loader first (load_rig_text):
/// a text it refuses is not written, and its errors are thrown. Returns the text written.
std::string save_rig_edits(const std::string& path, const std::string& loaded_text,
                           std::span<const MountEdit> edits);

}  // namespace rigdesign::io
