#!/usr/bin/env bash
# Regenerates renders/ (the pictures the README and docs/ show): the selection example's Pareto plot
# and chosen rig, and for the bundled rigs SC curves, cross-sections at 0, 45, 90 and 180
# degrees and the 3D views. Off-screen; no display needed.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh" >&2
. "$root/scripts/ninja_build_dir.sh"
ninja_build_dir "$root/build/release"
cmake -S "$root" -B "$root/build/release" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DRIGDESIGN_BUILD_TESTS=OFF >/dev/null
cmake --build "$root/build/release" --target rigdesign -j"$(nproc)" >/dev/null
cd "$root"
rm -rf renders/selection
./build/release/src/rigdesign select --catalog rigs/catalogs/ur_cleaner.yaml \
  --requirements rigs/requirements/ur_cleaner.yaml --policy rigs/policies/ur_cleaner.yaml \
  --budget 3000 --out renders/selection --no-renders
for rig in ur_cleaner elektron delivery_amr; do
  rm -rf "renders/$rig"
  ./build/release/src/rigdesign coverage "rigs/$rig.yaml" --out "renders/$rig" --angles 0,45,90,180
done
# The README and docs/ show the 3D views as PNG; their SVG twins embed the same pixels (large).
trap 'rm -f renders/*/view_*.svg' EXIT
# Real robots from their descriptions: the TurtleBot 4 (58 deg: behind a tower standoff, as
# the RPLIDAR sees it) and the Jackal.
rm -rf renders/turtlebot4 renders/jackal
./build/release/src/rigdesign coverage rigs/turtlebot4.yaml --out renders/turtlebot4 --angles 0,58,180
./build/release/src/rigdesign coverage rigs/jackal.yaml --out renders/jackal --angles 0,90,180
# Paper 1's Fig. 12: the four costmap variants on the wall-following scenario (final frames).
rm -rf renders/costmap
./build/release/src/rigdesign costmap --rig rigs/ur_cleaner.yaml --scenario wall_following --compare \
  --out renders/costmap
rm -rf renders/costmap/*/frames renders/costmap/*/final.svg
# Paper 3's cell: the occupancy sweep's Pareto plot and summary.
rm -rf renders/occupancy
./build/release/src/rigdesign occupancy --rig rigs/cell.yaml --scene cell --out renders/occupancy
rm -f renders/occupancy/occupancy_frames.csv
# Paper 4: a phone around a corner, and the hallway's two mirror hypotheses.
rm -rf renders/localize
for scenario in corner hallway; do
  ./build/release/src/rigdesign localize --scenario "$scenario" --seed 1 --checkpoints 0 \
    --out "renders/localize/$scenario"
  rm -f renders/localize/"$scenario"/*.svg renders/localize/"$scenario"/*.csv
done
