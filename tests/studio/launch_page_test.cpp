// Issue 53 item 2: `serve` opens the browser without the token on a command line. A stand-in
// browser on PATH copies the page it was given and waits; its arguments are read back from
// /proc/PID/cmdline, where any local user could read them, and the page's mode from stat.
#include "rigdesign/studio/launch_page.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

using namespace rigdesign;
namespace fs = std::filesystem;

namespace {

const std::string kToken = "00112233445566778899aabbccddeeff00112233445566778899aabbccddeeff";

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// PATH with `folder` first, for the test's length.
struct PathFirst {
  explicit PathFirst(const std::string& folder)
      : saved(std::getenv("PATH") ? std::getenv("PATH") : "") {
    ::setenv("PATH", (folder + ":" + saved).c_str(), 1);
  }
  ~PathFirst() { ::setenv("PATH", saved.c_str(), 1); }
  std::string saved;
};

}  // namespace

TEST_CASE("launch page: a 0600 page in a 0700 folder sends the browser on; no token in argv",
          "[studio]") {
  const std::string url = "http://127.0.0.1:8765/?token=" + kToken;
  const fs::path bin =
      fs::temp_directory_path() / ("rigdesign-launch-test-" + std::to_string(::getpid()));
  fs::create_directories(bin);
  const fs::path seen = bin / "seen.html";
  {
    std::ofstream script(bin / "rigdesign-stand-in-browser");
    script << "#!/bin/sh\ncp \"$1\" \"" << seen.string() << ".part\" && mv \"" << seen.string()
           << ".part\" \"" << seen.string() << "\"\nsleep 3\n";
  }
  fs::permissions(bin / "rigdesign-stand-in-browser", fs::perms::owner_all);
  PathFirst path_first(bin.string());

  std::string page_path;
  {
    const studio::LaunchPage page(url);
    page_path = page.path();
    struct stat file {};
    REQUIRE(::lstat(page_path.c_str(), &file) == 0);
    CHECK(S_ISREG(file.st_mode));
    CHECK((file.st_mode & 07777) == 0600);
    CHECK(file.st_uid == ::getuid());
    struct stat folder {};
    REQUIRE(::lstat(fs::path(page_path).parent_path().c_str(), &folder) == 0);
    CHECK(S_ISDIR(folder.st_mode));
    CHECK((folder.st_mode & 07777) == 0700);
    // The page carries the address: a redirect and a link to exactly it.
    const std::string html = read_text(page_path);
    CHECK(html.find("http-equiv=\"refresh\" content=\"0; url=" + url + "\"") != std::string::npos);
    CHECK(html.find("href=\"" + url + "\"") != std::string::npos);

    const std::optional<int> pid = studio::start_program("rigdesign-stand-in-browser", page_path);
    REQUIRE(pid);
    for (int i = 0; i < 100 && !fs::exists(seen); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    REQUIRE(fs::exists(seen));
    // The browser could read it (it got the token that way) ...
    CHECK(read_text(seen).find(url) != std::string::npos);
    // ... and its command line, readable by every user, holds the page's path, not the token.
    const std::string cmdline = read_text("/proc/" + std::to_string(*pid) + "/cmdline");
    CHECK(cmdline.find(page_path) != std::string::npos);
    CHECK(cmdline.find("token") == std::string::npos);
    CHECK(cmdline.find(kToken.substr(0, 16)) == std::string::npos);
  }
  // Gone with the page object (serve's end), folder and all.
  CHECK_FALSE(fs::exists(page_path));
  CHECK_FALSE(fs::exists(fs::path(page_path).parent_path()));
  // A missing program is reported, not thrown.
  CHECK_FALSE(studio::start_program("rigdesign-no-such-browser-program", "/nonexistent"));
  fs::remove_all(bin);
}

TEST_CASE("launch page: an address with HTML's own characters is refused", "[studio]") {
  for (const char* url :
       {"http://127.0.0.1:1/?token=\"><script>", "http://127.0.0.1:1/ x", "http://127.0.0.1:1/'"}) {
    INFO(url);
    CHECK_THROWS_AS(studio::LaunchPage(url), std::invalid_argument);
  }
}
