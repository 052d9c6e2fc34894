#include "rigdesign/studio/studio_assets.hpp"

#include <array>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "studio_page_files.hpp"

namespace rigdesign::studio {
namespace {

struct SystemFile {
  std::string_view url;
  std::string_view relative;  // under kThreeJsFolder
};

// three.js r111 as Debian ships it: the library and the three example scripts the page uses
// (their r111 forms define THREE.OrbitControls etc. as globals).
constexpr std::array<SystemFile, 4> kThreeFiles = {{
    {"/three/three.min.js", "three.min.js"},
    {"/three/OrbitControls.js", "examples/js/controls/OrbitControls.js"},
    {"/three/TransformControls.js", "examples/js/controls/TransformControls.js"},
    {"/three/GLTFLoader.js", "examples/js/loaders/GLTFLoader.js"},
}};

std::string read_system_file(std::string_view relative) {
  const std::string path = std::string(kThreeJsFolder) + "/" + std::string(relative);
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::runtime_error("cannot read " + path +
                             " (Debian's libjs-three; scripts/setup.sh installs it)");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

// Scripts as application/javascript with a charset, sent uncompressed (the earlier server,
// cpp-httplib, Brotli-compressed text/*: 850 ms for three.min.js on a loopback).
constexpr const char* kScriptType = "application/javascript; charset=utf-8";

std::optional<Asset> asset_at(std::string_view url_path) {
  if (url_path == "/" || url_path == "/index.html")
    return Asset{"text/html; charset=utf-8", std::string(kStudioPageHtml)};
  if (url_path == "/studio.js") return Asset{kScriptType, std::string(kStudioPageScript)};
  if (url_path == "/studio.css")
    return Asset{"text/css; charset=utf-8", std::string(kStudioPageStyle)};
  for (const SystemFile& file : kThreeFiles) {
    if (url_path == file.url) return Asset{kScriptType, read_system_file(file.relative)};
  }
  return std::nullopt;
}

}  // namespace rigdesign::studio
