#!/usr/bin/env bash
# Sets up, builds rigdesign (Release) and runs it. Without arguments it runs the main job on
# the bundled example; with arguments it runs `rigdesign ARGS...`.
#   scripts/run.sh                                  # select the UR Cleaner's rig under a budget
#   scripts/run.sh check rigs/*.yaml --format junit
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh" >&2
# Unity build, as CI's: the translation units CI compiles are the ones built here (a file
# missing an include once built in CI's unity groups and failed here), and it builds faster.
. "$root/scripts/ninja_build_dir.sh"
ninja_build_dir "$root/build/release"
cmake -S "$root" -B "$root/build/release" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DRIGDESIGN_BUILD_TESTS=OFF -DRIGDESIGN_UNITY_BUILD=ON >/dev/null
cmake --build "$root/build/release" --target rigdesign -j"$(nproc)" >/dev/null
cd "$root"
if [ $# -eq 0 ]; then
  set -- select --catalog rigs/catalogs/ur_cleaner.yaml \
    --requirements rigs/requirements/ur_cleaner.yaml \
    --policy rigs/policies/ur_cleaner.yaml --budget 3000 --out selection/ur_cleaner
fi
exec "$root/build/release/src/rigdesign" "$@"
