// The bad-input matrix of issue 16: every case exits 2, names the file with its line and
// column (counted here from the text this test writes, not by the loaders) or the option, and
// writes nothing into its output folder. Cases marked "issue 16" crashed, hung or answered
// wrongly before.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign::test;

namespace {

struct InputFile {
  std::string name;
  std::string text;
};

struct MatrixCase {
  std::string name;
  std::vector<InputFile> files;   // written into the case's folder first
  std::vector<std::string> args;  // "{dir}" is the case's folder, "{out}" its output folder
  std::string named;              // what the message must name; "{dir}" expands as above
};

std::string expand(std::string text, const std::string& dir) {
  for (std::size_t at = text.find("{dir}"); at != std::string::npos; at = text.find("{dir}"))
    text.replace(at, 5, dir);
  for (std::size_t at = text.find("{out}"); at != std::string::npos; at = text.find("{out}"))
    text.replace(at, 5, dir + "/out");
  return text;
}

std::string bundled(const std::string& relative) {
  std::ifstream stream(source_path(relative), std::ios::binary);
  std::stringstream text;
  text << stream.rdbuf();
  return text.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

// "file:line:" of the first line holding `marker` in `text`.
std::string at_line(const std::string& file, const std::string& text, const std::string& marker) {
  const int line = line_of(text, marker);
  REQUIRE(line > 0);
  return file + ":" + std::to_string(line) + ":";
}

int files_under(const std::string& folder) {
  std::error_code error;
  if (!std::filesystem::exists(folder, error)) return 0;
  int count = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder, error))
    count += entry.is_regular_file() ? 1 : 0;
  return count;
}

const std::string kRssi =
    "t,x,y,z,bssid,rssi\n"
    "0,0.0,0.0,0.4,02:00:00:00:00:01,-60\n"
    "1,0.5,0.1,0.4,02:00:00:00:00:01,-61\n"
    "2,1.0,0.2,0.4,02:00:00:00:00:01,-62\n";

const std::string kPcd =
    "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
    "WIDTH 3\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 3\nDATA ascii\n"
    "0.1 0.2 0.3\n1 2 3\n-1 -2 -3\n";

const std::string kScene =
    "name: s\nrobot_start: {xyz: [0, 0, 0], yaw_deg: 0}\nstatic:\n"
    "  - {name: box, mesh: nowhere.obj}\n";

std::vector<MatrixCase> option_cases() {
  const std::string rig = source_path("rigs/ur_cleaner.yaml");
  const std::string catalog = source_path("rigs/catalogs/ur_cleaner.yaml");
  const std::string requirements = source_path("rigs/requirements/ur_cleaner.yaml");
  const std::vector<std::string> select = {"select",     "--catalog", catalog, "--requirements",
                                           requirements, "--out",     "{out}"};
  const auto with = [](std::vector<std::string> base, std::vector<std::string> more) {
    base.insert(base.end(), more.begin(), more.end());
    return base;
  };
  const std::vector<std::string> localize = {"localize", "--scenario", "corner", "--out", "{out}"};
  const std::vector<std::string> costmap = {"costmap",    "--rig", rig,    "--scenario",
                                            "stationary", "--out", "{out}"};
  const std::vector<std::string> occupancy = {"occupancy", "--rig", source_path("rigs/cell.yaml"),
                                              "--out", "{out}"};
  return {
      {"select --budget inf (issue 16: hung in the Pareto plot)",
       {},
       with(select, {"--budget", "inf"}),
       "--budget: is inf"},
      {"select --budget 1e309 (issue 16)",
       {},
       with(select, {"--budget", "1e309"}),
       "--budget: is 1e309"},
      {"select --budget nan", {}, with(select, {"--budget", "nan"}), "--budget: is nan"},
      {"select --budget -5", {}, with(select, {"--budget", "-5"}), "--budget: is -5"},
      {"select --step 1e-9 (issue 16: angle count overflowed)",
       {},
       with(select, {"--budget", "3000", "--step", "1e-9"}),
       "--step: is 1e-9"},
      {"coverage --step 1e-9 (issue 16)",
       {},
       {"coverage", rig, "--step", "1e-9", "--out", "{out}"},
       "--step: is 1e-9"},
      {"coverage --step nan",
       {},
       {"coverage", rig, "--step", "nan", "--out", "{out}"},
       "--step: is nan"},
      {"coverage --angles with nan",
       {},
       {"coverage", rig, "--angles", "0,nan", "--out", "{out}"},
       "--angles: is nan"},
      {"localize --rssi-at-1m nan (issue 16: segfault)",
       {},
       with(localize, {"--rssi-at-1m", "nan"}),
       "--rssi-at-1m: is nan"},
      {"localize --cutoff nan (issue 16)",
       {},
       with(localize, {"--cutoff", "nan"}),
       "--cutoff: is nan"},
      {"localize --exponent-prior negative (issue 19)",
       {},
       with(localize, {"--exponent-prior", "-1"}),
       "--exponent-prior: is -1"},
      {"localize --mad-factor nan (issue 16)",
       {},
       with(localize, {"--mad-factor", "nan"}),
       "--mad-factor: is nan"},
      {"localize --time-constant negative (issue 16)",
       {},
       with(localize, {"--time-constant", "-3"}),
       "--time-constant: is -3"},
      {"localize --exponent 0", {}, with(localize, {"--exponent", "0"}), "--exponent: is 0"},
      {"localize --search-area with X0 > X1 (issue 33)",
       {},
       with(localize, {"--search-area", "5", "0", "1", "4"}),
       "--search-area: is 5 0 1 4"},
      {"localize --search-area of 20 km (issue 33)",
       {},
       with(localize, {"--search-area", "0", "0", "20000", "10"}),
       "--search-area: is 0 0 20000 10"},
      {"localize --search-area inf (issue 33)",
       {},
       with(localize, {"--search-area", "0", "0", "inf", "10"}),
       "--search-area: is inf"},
      {"localize --seeds 0", {}, with(localize, {"--seeds", "0"}), "--seeds: is 0"},
      {"costmap --speed inf (issue 16)", {}, with(costmap, {"--speed", "inf"}), "--speed: is inf"},
      {"costmap --resolution 0", {}, with(costmap, {"--resolution", "0"}), "--resolution: is 0"},
      {"costmap --update-rate nan",
       {},
       with(costmap, {"--update-rate", "nan"}),
       "--update-rate: is nan"},
      // One limit for the rate, the follower's 20 Hz control rate (issue 29: the option's check
      // allowed 100 Hz, then the command refused anything above 20 with another message).
      {"costmap --update-rate 50",
       {},
       with(costmap, {"--update-rate", "50"}),
       // 20 Hz control rate; at most 1200 control steps between updates: 20 / 1200 Hz.
       "--update-rate: is 50 (expected a rate in [0.0167, 20] Hz"},
      {"costmap --window -6", {}, with(costmap, {"--window", "-6"}), "--window: is -6"},
      {"occupancy --voxels 0", {}, with(occupancy, {"--voxels", "0"}), "--voxels: is 0"},
      {"occupancy --rate inf", {}, with(occupancy, {"--rate", "inf"}), "--rate: is inf"},
      {"occupancy --duration -1", {}, with(occupancy, {"--duration", "-1"}), "--duration: is -1"},
      {"simulate --frames 0", {}, {"simulate", rig, "--frames", "0", "--out", "{out}"}, "--frames"},
      {"simulate --frames 100000 states what it would write (issue 16: no bound, no estimate)",
       {},
       {"simulate", rig, "--frames", "100000", "--out", "{out}"},
       "--frames: 100000 frames of this rig would write about"},
      {"simulate --dropout 1",
       {},
       {"simulate", rig, "--dropout", "1", "--out", "{out}"},
       "--dropout"},
      {"filter --repeat 0",
       {{"c.pcd", kPcd}},
       {"filter", "--cloud", "{dir}/c.pcd", "--repeat", "0", "--out", "{out}"},
       "--repeat"},
      {"filter --threads 65 (issue 17: 1 to 64)",
       {{"c.pcd", kPcd}},
       {"filter", "--cloud", "{dir}/c.pcd", "--threads", "65", "--out", "{out}"},
       "--threads: is out of range"},
      {"export --max-speed nan",
       {},
       {"export", rig, "--to", "{out}", "--max-speed", "nan"},
       "--max-speed: is nan"},
      {"an unknown subcommand is named (issue 16)",
       {},
       {"frobnicate", rig},
       "unknown subcommand 'frobnicate'"},
  };
}

// --out under a regular file: every command says so before it works (issue 16: simulate,
// filter, localize and costmap threw std::filesystem::filesystem_error, exit 134).
std::vector<MatrixCase> output_cases() {
  const std::string rig = source_path("rigs/ur_cleaner.yaml");
  const InputFile blocker{"blocker", "a regular file where a folder is wanted\n"};
  const std::string named = "--out: '{dir}/blocker/out' cannot be created: Not a directory";
  return {
      {"simulate --out under a file",
       {blocker},
       {"simulate", rig, "--scene", "corridor", "--out", "{dir}/blocker/out"},
       named},
      {"filter --out under a file",
       {blocker, {"c.pcd", kPcd}},
       {"filter", "--cloud", "{dir}/c.pcd", "--out", "{dir}/blocker/out"},
       named},
      {"localize --out under a file",
       {blocker},
       {"localize", "--scenario", "corner", "--out", "{dir}/blocker/out"},
       named},
      {"costmap --out under a file",
       {blocker},
       {"costmap", "--rig", rig, "--scenario", "stationary", "--out", "{dir}/blocker/out"},
       named},
      {"coverage --out under a file",
       {blocker},
       {"coverage", rig, "--out", "{dir}/blocker/out"},
       named},
      {"occupancy --out under a file",
       {blocker},
       {"occupancy", "--rig", source_path("rigs/cell.yaml"), "--out", "{dir}/blocker/out"},
       named},
      {"select --out under a file fails before the search (issue 16: after 28-43 s)",
       {blocker},
       {"select", "--catalog", source_path("rigs/catalogs/ur_cleaner.yaml"), "--requirements",
        source_path("rigs/requirements/ur_cleaner.yaml"), "--budget", "3000", "--out",
        "{dir}/blocker/out"},
       named},
  };
}

std::vector<MatrixCase> file_cases() {
  const std::string rig_text = bundled("rigs/ur_cleaner.yaml");
  const std::string catalog_text = bundled("rigs/catalogs/ur_cleaner_pose_ranges.yaml");
  const std::string requirements_text = bundled("rigs/requirements/ur_cleaner.yaml");
  const std::string policy_text = bundled("rigs/policies/ur_cleaner.yaml");
  const std::string requirements = source_path("rigs/requirements/ur_cleaner.yaml");
  const std::string catalog = source_path("rigs/catalogs/ur_cleaner.yaml");
  const std::string sensors = source_path("sensors.yaml");
  const auto select_catalog = [&](const std::string& path) {
    return std::vector<std::string>{"select",     "--catalog", path,    "--requirements",
                                    requirements, "--sensors", sensors, "--budget",
                                    "3000",       "--out",     "{out}"};
  };
  const auto log_case = [](const std::string& name, const std::string& text,
                           const std::string& named) {
    return MatrixCase{
        name, {{"log.csv", text}}, {"localize", "--log", "{dir}/log.csv", "--out", "{out}"}, named};
  };
  const auto cloud_case = [](const std::string& name, const std::string& file,
                             const std::string& text, const std::string& named) {
    return MatrixCase{
        name, {{file, text}}, {"filter", "--cloud", "{dir}/" + file, "--out", "{out}"}, named};
  };
  // A rig beside the bundled library, its name in Latin-1 (issue 16: uncaught
  // nlohmann::type_error 316 in the JSON reports).
  const std::string latin1_rig = replaced(rig_text, "name: UR Cleaner", "name: K\xe4rcher cleaner");
  const std::string latin1_at =
      "{dir}/rig.yaml:" + std::to_string(line_of(latin1_rig, "name: K")) + ":8: (encoding)";
  const std::string pose_ranges_with_library =
      replaced(catalog_text, "sensor_library: ../../sensors.yaml", "sensor_library: " + sensors);
  const auto catalog_case = [&](const std::string& name, const std::string& from,
                                const std::string& to, const std::string& field) {
    const std::string text = replaced(pose_ranges_with_library, from, to);
    return MatrixCase{name,
                      {{"catalog.yaml", text}},
                      select_catalog("{dir}/catalog.yaml"),
                      at_line("{dir}/catalog.yaml", text, to) + field};
  };
  const std::string bad_policy = replaced(policy_text, "{relax: robot_speed.max_speed, to: 0.8}",
                                          "{relax: robot_speed.top_speed, to: 0.8}");
  const std::string bad_requirements =
      replaced(requirements_text, "max_speed: 1.0", "max_speed: .nan");
  return {
      {"check --format json on a Latin-1 rig name (issue 16)",
       {{"rig.yaml", latin1_rig}},
       {"check", "{dir}/rig.yaml", "--format", "json"},
       latin1_at},
      {"metrics --json on a Latin-1 rig name (issue 16)",
       {{"rig.yaml", latin1_rig}},
       {"metrics", "{dir}/rig.yaml", "--json"},
       latin1_at},
      {"a folder given as the rig", {}, {"metrics", "{dir}"}, "{dir}: file: is a folder"},
      {"a folder given as --requirements",
       {},
       {"metrics", source_path("rigs/ur_cleaner.yaml"), "--requirements", "{dir}"},
       "{dir}: file: is a folder"},
      {"a folder given as a cloud",
       {},
       {"filter", "--cloud", "{dir}", "--out", "{out}"},
       "is neither a .pcd nor a .ply file"},
      {"a missing rig",
       {},
       {"metrics", "{dir}/nope.yaml"},
       "{dir}/nope.yaml: file: cannot be opened: No such file or directory"},
      cloud_case("a cloud with a point at x = 3e19 (issue 16: SIGSEGV in the outlier filter)",
                 "far.pcd", replaced(kPcd, "1 2 3\n", "3e19 2 3\n"),
                 "{dir}/far.pcd: point 1: lies at (3e+19, 2, 3) m"),
      cloud_case("a PCD whose POINTS disagree with WIDTH x HEIGHT", "w.pcd",
                 replaced(kPcd, "POINTS 3", "POINTS 4"), "{dir}/w.pcd:10:"),
      cloud_case("a PCD with a word for a coordinate", "t.pcd",
                 replaced(kPcd, "1 2 3\n", "1 two 3\n"), "{dir}/t.pcd:13:"),
      cloud_case("a PCD cut short", "s.pcd", replaced(kPcd, "-1 -2 -3\n", ""),
                 "the ascii body ends after 2 of 3 points"),
      cloud_case("a PLY with an unknown format", "f.ply",
                 "ply\nformat utf8 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                 "property float z\nend_header\n0 0 0\n",
                 "{dir}/f.ply:2:"),
      cloud_case("an empty cloud file", "e.pcd", "", "{dir}/e.pcd"),
      {"a PCD header in Latin-1 (its names reach filter --json)",
       {{"l.pcd", replaced(kPcd, "# .PCD v0.7", "# .PCD v0.7 K\xe4rcher")}},
       {"filter", "--cloud", "{dir}/l.pcd", "--json", "--out", "{out}"},
       "{dir}/l.pcd:1:14: (encoding)"},
      log_case("an RSSI log 1e15 m long (issue 16: length_error in the object map)",
               replaced(kRssi, "2,1.0,0.2", "2,1e15,0.2"), "{dir}/log.csv:4:3: x: '1e15' m lies"),
      log_case("an RSSI log with a Latin-1 BSSID",
               replaced(kRssi, "-61", "-61\n3,1,1,0.4,caf\xe9,-62"),
               "{dir}/log.csv:4:14: (encoding)"),
      log_case("an RSSI log with nan dBm", replaced(kRssi, "-62", "nan"),
               "{dir}/log.csv:4:33: rssi"),
      log_case("an RSSI log without the rssi column", "t,x,y,z,bssid\n0,0,0,0,aa\n",
               "{dir}/log.csv:1:"),
      log_case("a CO2 log with a negative concentration", "t,x,y,z,co2_ppm\n0,0,0,0,-5\n",
               "{dir}/log.csv:2:9:"),
      log_case("a log that is empty", "", "{dir}/log.csv"),
      catalog_case("a pose range with step 0", "{min: 10, max: 40, step: 5}",
                   "{min: 10, max: 40, step: 0}", ""),
      catalog_case("a pose range with min > max", "{min: 10, max: 40, step: 5}",
                   "{min: 40, max: 10, step: 5}", ""),
      catalog_case("a pose range whose step does not divide it", "{min: 10, max: 40, step: 5}",
                   "{min: 10, max: 40, step: 7}", ""),
      {"a catalog whose rasters would outgrow memory is refused before rasterising",
       {{"catalog.yaml", replaced(pose_ranges_with_library, "{min: 10, max: 40, step: 5}",
                                  "{min: 10, max: 40, step: 0.1}")}},
       [&] {
         std::vector<std::string> args = select_catalog("{dir}/catalog.yaml");
         args.insert(args.end(), {"--step", "0.25"});  // 1440 angles per option
         return args;
       }(),
       "--catalog: {dir}/catalog.yaml has "},
      {"a policy step relaxing an unknown requirement",
       {{"policy.yaml", bad_policy}},
       {"select", "--catalog", catalog, "--requirements", requirements, "--policy",
        "{dir}/policy.yaml", "--budget", "3000", "--out", "{out}"},
       at_line("{dir}/policy.yaml", bad_policy, "top_speed")},
      {"a requirement that is nan",
       {{"req.yaml", bad_requirements}},
       {"select", "--catalog", catalog, "--requirements", "{dir}/req.yaml", "--budget", "3000",
        "--out", "{out}"},
       at_line("{dir}/req.yaml", bad_requirements, ".nan")},
      {"a pipeline with a leaf of 0",
       {{"c.pcd", kPcd}, {"p.yaml", "name: p\nstages:\n  - voxel_grid: {leaf: 0}\n"}},
       {"filter", "--cloud", "{dir}/c.pcd", "--pipeline", "{dir}/p.yaml", "--out", "{out}"},
       "{dir}/p.yaml:3:"},
      {"a pipeline with an unknown stage",
       {{"c.pcd", kPcd}, {"p.yaml", "name: p\nstages:\n  - voxel_grid: {leaf: 0.1}\n  - smooth\n"}},
       {"filter", "--cloud", "{dir}/c.pcd", "--pipeline", "{dir}/p.yaml", "--out", "{out}"},
       "{dir}/p.yaml:4:"},
      {"a voxel leaf too small for the cloud names the cloud (issue 16: named no file)",
       {{"wide.pcd", replaced(kPcd, "-1 -2 -3", "-90000 -2 -3")},
        {"p.yaml", "name: p\nstages:\n  - voxel_grid: {leaf: 0.01}\n"}},
       {"filter", "--cloud", "{dir}/wide.pcd", "--pipeline", "{dir}/p.yaml", "--out", "{out}"},
       "{dir}/wide.pcd: voxel_grid.leaf: is too small"},
      {"costmap parameters with an unknown key",
       {{"params.yaml",
         "local_costmap:\n  local_costmap:\n    ros__parameters:\n"
         "      resolution: 0.05\n      rezolution: 0.05\n"}},
       {"costmap", "--rig", source_path("rigs/ur_cleaner.yaml"), "--scenario", "stationary",
        "--params", "{dir}/params.yaml", "--out", "{out}"},
       "{dir}/params.yaml:5:"},
      {"costmap parameters with a negative resolution",
       {{"params.yaml",
         "local_costmap:\n  local_costmap:\n    ros__parameters:\n      resolution: -0.05\n"}},
       {"costmap", "--rig", source_path("rigs/ur_cleaner.yaml"), "--scenario", "stationary",
        "--params", "{dir}/params.yaml", "--out", "{out}"},
       "{dir}/params.yaml:4:"},
      {"a sensors.yaml in Latin-1",
       {{"sensors.yaml", replaced(bundled("sensors.yaml"), "name: ", "name: \xb5")}},
       {"metrics", source_path("rigs/ur_cleaner.yaml"), "--sensors", "{dir}/sensors.yaml"},
       "{dir}/sensors.yaml:"},
      {"a scene file naming a mesh that does not exist",
       {{"scene.yaml", kScene}},
       {"simulate", source_path("rigs/ur_cleaner.yaml"), "--scene", "{dir}/scene.yaml", "--out",
        "{out}"},
       at_line("{dir}/scene.yaml", kScene, "nowhere.obj")},
      {"an OBJ mesh whose face names a missing vertex",
       {{"scene.yaml", replaced(kScene, "nowhere.obj", "box.obj")},
        {"box.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"}},
       {"simulate", source_path("rigs/ur_cleaner.yaml"), "--scene", "{dir}/scene.yaml", "--out",
        "{out}"},
       "{dir}/box.obj:4:"},
  };
}

void check_case(const MatrixCase& bad) {
  TempFolder folder;
  for (const InputFile& file : bad.files) folder.write(file.name, file.text);
  std::vector<std::string> args;
  for (const std::string& arg : bad.args) args.push_back(expand(arg, folder.path()));
  const CliResult result = run_cli(args);
  const std::string named = expand(bad.named, folder.path());
  INFO("out: " << result.out << "\nerr: " << result.err);
  CHECK(result.exit_code == 2);
  CHECK((result.err + result.out).find(named) != std::string::npos);
  CHECK(files_under(folder.path() + "/out") == 0);  // nothing written, not even in part
}

}  // namespace

TEST_CASE("bad input matrix: options") {
  for (const MatrixCase& bad : option_cases()) {
    DYNAMIC_SECTION(bad.name) {
      check_case(bad);
    }
  }
}

TEST_CASE("bad input matrix: output folders") {
  for (const MatrixCase& bad : output_cases()) {
    DYNAMIC_SECTION(bad.name) {
      check_case(bad);
    }
  }
}

TEST_CASE("bad input matrix: files") {
  for (const MatrixCase& bad : file_cases()) {
    DYNAMIC_SECTION(bad.name) {
      check_case(bad);
    }
  }
}

TEST_CASE("bad input matrix: at least 60 cases") {
  CHECK(option_cases().size() + output_cases().size() + file_cases().size() >= 60);
}
