#!/usr/bin/env bash
# Builds the benchmarks (Release, no sanitizers) and runs them; prints medians.
#   scripts/bench.sh                 # every benchmark
#   scripts/bench.sh coverage        # one benchmark binary
#   scripts/bench.sh filters         # ours vs PCL (installs libpcl-dev first)
#   scripts/bench.sh occupancy       # ours vs OctoMap on the cell (installs liboctomap-dev first)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh" >&2
if [ "${1:-}" = "filters" ]; then "$root/scripts/install-pcl.sh" >&2; fi
if [ "${1:-}" = "occupancy" ]; then "$root/scripts/install-octomap.sh" >&2; fi
build="$root/build/bench"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DRIGDESIGN_BUILD_TESTS=OFF \
  -DRIGDESIGN_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$build" -j"$(nproc)" >/dev/null
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
for bench in "$build"/tests/bench/*_bench; do
  name="$(basename "$bench" _bench)"
  if [ "$name" = "filters_vs_pcl" ]; then
    if [ $# -eq 0 ] || [ "$1" = "filters" ]; then "$bench"; fi
    continue
  fi
  if [ "$name" = "occupancy_vs_octomap" ]; then
    if [ $# -eq 0 ] || [ "$1" = "occupancy" ]; then "$bench"; fi
    continue
  fi
  if [ $# -gt 0 ] && [ "$1" != "$name" ]; then continue; fi
  "$bench" --benchmark_format=console
done
