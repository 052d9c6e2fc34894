// Issue 53 item 1: a save replaces a user's file keeping what makes it theirs: its mode, owner,
// group and hard links (io::replace_file_keeping_identity). The modes, owners and texts below
// are set by the test itself, then read back from the file system.
#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>

#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/model/input_error.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;

namespace {

struct stat status_of(const std::string& path) {
  struct stat found {};
  REQUIRE(::stat(path.c_str(), &found) == 0);
  return found;
}

}  // namespace

TEST_CASE("replacing a file keeps its mode, group and owner, and leaves no temporary",
          "[io][save]") {
  test::TempFolder folder;
  for (const mode_t mode : {mode_t{0600}, mode_t{0664}, mode_t{0640}}) {
    const std::string path = folder.write("rig.yaml", "name: old\n");
    REQUIRE(::chmod(path.c_str(), mode) == 0);
    const struct stat before = status_of(path);
    io::replace_file_keeping_identity(path, "name: new\n");
    const struct stat after = status_of(path);
    CHECK((after.st_mode & 07777) == mode);
    CHECK(after.st_uid == before.st_uid);
    CHECK(after.st_gid == before.st_gid);
    CHECK(test::file_text(path) == "name: new\n");
    CHECK(folder.entries() == 1);
  }
  // Another owner and group: kept by root (the temporary is given them before the rename);
  // anyone else cannot give a file away and writes in place, which keeps them as well.
  if (::geteuid() == 0) {
    const std::string path = folder.write("theirs.yaml", "name: old\n");
    const uid_t owner = 4321;  // no account needed: a number the test picks
    const gid_t group = 4322;
    REQUIRE(::chown(path.c_str(), owner, group) == 0);
    REQUIRE(::chmod(path.c_str(), 0660) == 0);
    io::replace_file_keeping_identity(path, "name: new\n");
    const struct stat after = status_of(path);
    CHECK(after.st_uid == owner);
    CHECK(after.st_gid == group);
    CHECK((after.st_mode & 07777) == 0660);
    CHECK(test::file_text(path) == "name: new\n");
  }
}

TEST_CASE("replacing a file with a second hard link writes it in place: both names see it",
          "[io][save]") {
  test::TempFolder folder;
  const std::string path = folder.write("rig.yaml", "name: a much longer old text\n# more\n");
  const std::string other = folder.path() + "/other_name.yaml";
  std::filesystem::create_hard_link(path, other);
  REQUIRE(::chmod(path.c_str(), 0640) == 0);
  const struct stat before = status_of(path);
  io::replace_file_keeping_identity(path, "name: new\n");
  const struct stat after = status_of(path);
  CHECK(after.st_ino == before.st_ino);
  CHECK(after.st_nlink == 2);
  CHECK((after.st_mode & 07777) == 0640);
  // Shorter than the old text: cut to its length.
  CHECK(test::file_text(path) == "name: new\n");
  CHECK(test::file_text(other) == "name: new\n");
  CHECK(folder.entries() == 2);  // the two names, no temporary
}

TEST_CASE("replacing refuses what is not a writable regular file, and changes nothing",
          "[io][save]") {
  test::TempFolder folder;
  const std::string real = folder.write("real.yaml", "name: old\n");
  const std::string link = folder.path() + "/link.yaml";
  std::filesystem::create_symlink(real, link);
  CHECK_THROWS_AS(io::replace_file_keeping_identity(link, "name: new\n"), model::InputError);
  CHECK(std::filesystem::is_symlink(link));
  CHECK(test::file_text(real) == "name: old\n");
  CHECK_THROWS_AS(io::replace_file_keeping_identity(folder.path() + "/missing.yaml", "x"),
                  model::InputError);
  // Read-only: refused (root may write anything, so only checked for other users).
  if (::geteuid() != 0) {
    REQUIRE(::chmod(real.c_str(), 0444) == 0);
    CHECK_THROWS_AS(io::replace_file_keeping_identity(real, "name: new\n"), model::InputError);
    CHECK(test::file_text(real) == "name: old\n");
  }
  CHECK(folder.entries() == 2);
}
