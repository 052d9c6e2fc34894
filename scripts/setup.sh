#!/usr/bin/env bash
# Installs the Debian 12 packages rigdesign needs. Idempotent: runs apt-get (update first) only
# when a package is missing. Needs root, or sudo.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git   # compiler and build
  ninja-build                            # builds every module's objects at once (CI time)
  libeigen3-dev                          # linear algebra, poses
  libyaml-cpp-dev                        # sensors.yaml, rigs, requirements (with line/column marks)
  nlohmann-json3-dev                     # --json and --format json reports
  libcli11-dev                           # command line
  catch2                                 # unit tests
  libcgal-dev libgmp-dev libmpfr-dev     # exact 2D Boolean operations, AABB-tree ray casting
  libosmesa6-dev                         # off-screen 3D renders of FOV volumes
  libcairo2-dev                          # 2D charts, cross-section images, text, PNG and SVG
  liburdfdom-dev                         # mount poses from a robot's URDF
  libsdformat-dev                        # tests: Gazebo's own SDF parser reads the exported sensors
  libtinyxml2-dev                        # xacro robot descriptions, parsed with line numbers
  libassimp-dev                          # collision meshes of robot descriptions (STL, COLLADA, OBJ)
  liboctomap-dev                         # paper 3's OctoMap in `occupancy --sweep octomap:*`
  python3                                # an independent XML parser for the JUnit test; fuzz seeds
  python3-yaml                           # an independent YAML parser for the exported files (tests)
  clang libclang-rt-14-dev               # libFuzzer and its runtime for the fuzz targets (fuzz/)
  clang-format                           # tests: every C++ file as .clang-format lays it out
  llvm                                   # llvm-symbolizer: readable stacks in fuzz findings
  libbenchmark-dev                       # Google Benchmark for scripts/bench.sh
  fonts-dejavu-core                      # the font Cairo draws labels with
  chromium                               # headless browser: the test that renders `report`'s page
  chromium-driver                        # WebDriver for chromium: the studio's browser test (serve)
  libmicrohttpd-dev                      # `serve`: the studio's loopback HTTP server (GNU; bounds
                                         # heads, epoll: idle strangers hold no thread)
  libjs-three                            # `serve`: three.js for the studio page, served locally
  python3-ament-index                    # tests: ROS 2's package index finds the installed prefix
  colcon python3-colcon-ros python3-colcon-cmake python3-colcon-metadata  # rigdesign in a ROS 2
  python3-colcon-package-information python3-colcon-recursive-crawl      # workspace (package.xml)
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
