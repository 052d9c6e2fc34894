#pragma once
#include <string>

namespace rigdesign::io {

/// Writes `contents` to a temporary file beside `path` and renames it over `path`, so a
/// reader never sees a half-written file and a failure leaves nothing behind.
/// Throws InputError (field "output") when the folder is not writable.
void write_file_atomically(const std::string& path, const std::string& contents);

/// Replaces the text of a user's existing regular file `path` with `contents`, keeping what
/// makes it that file: its mode, owner and group, its extended attributes (ACLs) and every hard
/// link to it. The new text is first written and synced to a private (0600) temporary beside
/// it. When that temporary can take the file's identity (one link, no extended attributes, its
/// owner and group settable: the file is ours, or we are root) it is renamed over the file, so
/// a reader never sees half the text. Otherwise the file is rewritten in place and synced, and
/// the temporary removed after: a crash in between leaves the new text complete in it; a write
/// that fails puts the old text back. Throws InputError (field "output") when `path` is not a
/// regular file, is not writable by us, or a write fails; nothing is changed then, unless the
/// message says where the new text was left.
void replace_file_keeping_identity(const std::string& path, const std::string& contents);

}  // namespace rigdesign::io
