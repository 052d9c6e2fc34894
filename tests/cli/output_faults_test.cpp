// Issue 16, faults: a run killed with SIGKILL at any point leaves the previous outputs or the
// complete new set (never a truncated file, never a mix), and a full disk gives exit 2 with
// the cause and leaves nothing behind. Runs the CLI in a forked child so it can be killed.
#include <sys/mount.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

#include "rigdesign/io/cloud/cloud_io.hpp"
#include "support/cli_runner.hpp"
#include "support/run_in_child.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;
namespace fs = std::filesystem;

namespace {

// Whether a file is whole by its own format's rules, independently of the writer.
bool parses(const std::string& name, const std::string& bytes) {
  const auto ends_with = [&](const std::string& tail) {
    return bytes.size() >= tail.size() &&
           bytes.compare(bytes.size() - tail.size(), tail.size(), tail) == 0;
  };
  const std::string extension = fs::path(name).extension().string();
  if (extension == ".png") {  // signature first, IEND chunk with its CRC last
    return bytes.rfind("\x89PNG\r\n\x1a\n", 0) == 0 &&
           ends_with(std::string("IEND\xae\x42\x60\x82", 8));
  }
  if (extension == ".svg") return ends_with("</svg>\n") || ends_with("</svg>");
  if (extension == ".json" || extension == ".yaml") {
    try {
      YAML::Load(bytes);
      return !bytes.empty();
    } catch (const YAML::Exception&) {
      return false;
    }
  }
  if (extension == ".csv") return !bytes.empty() && bytes.back() == '\n';
  // The export's README opens with its title and ends its last line.
  if (extension == ".md") return bytes.rfind("# ", 0) == 0 && ends_with("\n");
  // The exported macro closes its root element; the launch file ends its function's return.
  if (extension == ".xacro") return ends_with("</robot>\n");
  if (extension == ".py")
    return bytes.find("def generate_launch_description") != std::string::npos && ends_with("\n");
  if (extension == ".pcd") {
    const fs::path copy = fs::temp_directory_path() /
                          ("rigdesign_fault_check_" + std::to_string(::getpid()) + ".pcd");
    std::ofstream(copy, std::ios::binary) << bytes;
    try {
      io::read_cloud(copy.string());
      fs::remove(copy);
      return true;
    } catch (...) {
      fs::remove(copy);
      return false;
    }
  }
  return name == ".rigdesign-output";
}

// Kills per command: each costs three runs (old, killed new, new) under the sanitizers.
constexpr int kKills = 4;

void check_kills(const std::vector<std::string>& old_args, const std::vector<std::string>& new_args,
                 const std::string& folder) {
  // The two complete sets, made without interruption.
  REQUIRE(run_in_child(old_args) == 0);
  const Snapshot old_set = snapshot(folder);
  const auto start = std::chrono::steady_clock::now();
  REQUIRE(run_in_child(new_args) == 0);
  const auto full_run = std::chrono::steady_clock::now() - start;
  const Snapshot new_set = snapshot(folder);
  REQUIRE(!old_set.empty());
  REQUIRE(!new_set.empty());
  REQUIRE(old_set != new_set);
  for (const auto& [name, bytes] : new_set) CHECK(parses(name, bytes));

  std::mt19937 rng(16);
  std::uniform_real_distribution<double> share(0.0, 1.2);
  int kept_old = 0, got_new = 0;
  for (int attempt = 0; attempt < kKills; ++attempt) {
    REQUIRE(run_in_child(old_args) == 0);
    INFO("differing: " << differences(snapshot(folder), old_set));
    REQUIRE(snapshot(folder) == old_set);
    const auto delay = std::chrono::duration_cast<std::chrono::microseconds>(full_run * share(rng));
    run_and_kill(new_args, delay);
    const Snapshot after = snapshot(folder);
    INFO("killed after " << delay.count() << " us of a "
                         << std::chrono::duration_cast<std::chrono::microseconds>(full_run).count()
                         << " us run");
    CHECK((after == old_set || after == new_set));
    kept_old += after == old_set ? 1 : 0;
    got_new += after == new_set ? 1 : 0;
    // A killed run's staging folder is hidden beside the output and removed by the next run.
    REQUIRE(run_in_child(new_args) == 0);
    CHECK(snapshot(folder) == new_set);
  }
  CHECK(kept_old + got_new == kKills);
}

}  // namespace

TEST_CASE("kill -9 during coverage leaves the old pictures or the complete new set") {
  TempFolder folder;
  const std::string out = folder.path() + "/coverage";
  check_kills(
      {"coverage", source_path("rigs/elektron.yaml"), "--out", out, "--raster", "--no-3d"},
      {"coverage", source_path("rigs/ur_cleaner.yaml"), "--out", out, "--raster", "--no-3d"}, out);
  // Nothing else was left beside the folder: staging folders of killed runs are gone.
  int entries = 0;
  for (const auto& entry : fs::directory_iterator(folder.path())) entries += entry.exists() ? 1 : 0;
  CHECK(entries == 1);
}

TEST_CASE("kill -9 during simulate leaves the old clouds or the complete new set") {
  TempFolder folder;
  const std::string out = folder.path() + "/clouds";
  // Two 2D scanners: small clouds, many files, a run short enough to kill repeatedly.
  const std::string rig = source_path("rigs/cart_two_scanners.yaml");
  check_kills(
      {"simulate", rig, "--scene", "corridor", "--frames", "3", "--seed", "1", "--out", out},
      {"simulate", rig, "--scene", "corridor", "--frames", "6", "--seed", "2", "--out", out}, out);
}

TEST_CASE("a full disk is exit 2 with the cause, and leaves the previous outputs whole") {
  TempFolder folder;
  const std::string disk = folder.path() + "/small_disk";
  fs::create_directories(disk);
  // A 256 KiB tmpfs holds the old outputs of a small run but not a new coverage set.
  if (::mount("tmpfs", disk.c_str(), "tmpfs", 0, "size=256k") != 0) {
    WARN("cannot mount a tmpfs here (needs root): the full-disk case was not run");
    return;
  }
  const std::string out = disk + "/out";
  std::ofstream(out + "_placeholder") << "";
  fs::create_directories(out);
  std::ofstream(out + "/.rigdesign-output") << "previous run\n";
  std::ofstream(out + "/coverage.csv") << "angle,complete\n0,0.5\n";
  const Snapshot before = snapshot(out);
  const CliResult result =
      run_cli({"coverage", source_path("rigs/ur_cleaner.yaml"), "--out", out, "--raster"});
  INFO(result.err);
  CHECK(result.exit_code == 2);
  CHECK(result.err.find("No space left on device") != std::string::npos);
  CHECK(snapshot(out) == before);
  int entries = 0;
  for (const auto& entry : fs::directory_iterator(disk)) entries += entry.exists() ? 1 : 0;
  CHECK(entries == 2);  // the folder and the placeholder: no staging folder, no temp file
  ::umount(disk.c_str());
}

TEST_CASE("kill -9 during export leaves the old deployment files or the new set (09)") {
  TempFolder folder;
  const std::string out = folder.path() + "/deploy";
  check_kills({"export", source_path("rigs/cart_two_scanners.yaml"), "--to", out},
              {"export", source_path("rigs/ur_cleaner.yaml"), "--to", out}, out);
}

TEST_CASE(
    "export on a full disk: exit 2 naming the file as the user knows it, old set whole (08)") {
  TempFolder folder;
  const std::string disk = folder.path() + "/small_disk";
  fs::create_directories(disk);
  if (::mount("tmpfs", disk.c_str(), "tmpfs", 0, "size=64k") != 0) {
    WARN("cannot mount a tmpfs here (needs root): the full-disk export was not run");
    return;
  }
  const std::string out = disk + "/exp";
  REQUIRE(run_cli({"export", source_path("rigs/cart_two_scanners.yaml"), "--to", out}).exit_code ==
          0);
  const Snapshot before = snapshot(out);
  // Fill the disk but for 4 KiB: the new set cannot be staged.
  const auto space = fs::space(disk);
  std::ofstream(disk + "/filler", std::ios::binary) << std::string(
      static_cast<std::size_t>(space.available > 4096 ? space.available - 4096 : 0), '\0');
  const CliResult result = run_cli({"export", source_path("rigs/ur_cleaner.yaml"), "--to", out});
  INFO(result.err);
  CHECK(result.exit_code == 2);
  CHECK(result.err.find("No space left on device") != std::string::npos);
  CHECK(result.err.find(".partial-") == std::string::npos);  // not the hidden staging path
  CHECK(snapshot(out) == before);
  ::umount(disk.c_str());
}

TEST_CASE("an output folder holding one of the command's inputs is refused before any work (19)") {
  TempFolder folder;
  const std::string out = folder.path() + "/selection";
  fs::create_directories(out);
  std::ofstream(out + "/.rigdesign-output") << "written by rigdesign\n";  // as select leaves it
  fs::copy_file(source_path("rigs/ur_cleaner.yaml"), out + "/chosen_rig.yaml");
  fs::copy_file(source_path("rigs/requirements/ur_cleaner.yaml"), out + "/requirements.yaml");
  fs::create_directories(out + "/deep/er");
  fs::copy_file(source_path("rigs/ur_cleaner.yaml"), out + "/deep/er/rig.yaml");
  const Snapshot before = snapshot(out);
  const std::string rig = out + "/chosen_rig.yaml";
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"report", rig, "--sensors", source_path("sensors.yaml"),
                                 "--requirements", out + "/requirements.yaml", "--out", out},
        std::vector<std::string>{"coverage", rig, "--sensors", source_path("sensors.yaml"),
                                 "--requirements", out + "/requirements.yaml", "--out", out},
        std::vector<std::string>{"export", rig, "--sensors", source_path("sensors.yaml"),
                                 "--requirements", out + "/requirements.yaml", "--to", out},
        // The input two levels down, the folder named through another spelling.
        std::vector<std::string>{"report", out + "/deep/er/rig.yaml", "--sensors",
                                 source_path("sensors.yaml"), "--requirements",
                                 out + "/requirements.yaml", "--out", out + "/deep/../"}}) {
    const CliResult result = run_cli(args);
    INFO(args.front() << ": " << result.err);
    CHECK(result.exit_code == 2);
    CHECK(result.err.find("holds the input") != std::string::npos);
  }
  CHECK(snapshot(out) == before);
}
