#pragma once
/// The files the studio's page is made of, and nothing else: its own page, script and style
/// (compiled into the program) and three.js from Debian's libjs-three, read from its fixed
/// install path. A URL path is looked up in this table exactly, so no request names a file.
#include <optional>
#include <string>
#include <string_view>

namespace rigdesign::studio {

struct Asset {
  std::string content_type;
  std::string body;
};

/// The asset served at `url_path` ("/", "/studio.js", "/three/three.min.js", ...), or nothing
/// for a path not in the table. Throws std::runtime_error when a table entry's system file
/// cannot be read (libjs-three missing: scripts/setup.sh installs it).
std::optional<Asset> asset_at(std::string_view url_path);

/// Where Debian's libjs-three puts three.js (the folder holding three.min.js and examples/).
inline constexpr std::string_view kThreeJsFolder = "/usr/share/javascript/three";

}  // namespace rigdesign::studio
