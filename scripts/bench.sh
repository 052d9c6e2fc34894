#!/usr/bin/env bash
# Builds the benchmarks (Release, no sanitizers) and runs them; prints medians, with the
# machine and its load, so one run regenerates every speed table of docs/benchmarks.md.
#   scripts/bench.sh                 # every benchmark (installs the PCL and OctoMap peers first)
#   scripts/bench.sh coverage        # one Google Benchmark binary: coverage, select, costmap, localize
#   scripts/bench.sh filters         # ours vs PCL (as shipped and serial), and the growth curve
#   scripts/bench.sh occupancy       # ours vs OctoMap on the cell
#   scripts/bench.sh localize_matrix # the localisation test matrix (independent generator):
#                                    # errors against paper 4's WLS and 95 % region coverage
#   scripts/bench.sh paper2_table1   # paper 2's Table 1 on rigs/elektron.yaml: 3 variants x 20
#                                    # seeds in office_goals with DWA, the critical-distance
#                                    # sweep included (issue 35: under 5 minutes here); the
#                                    # orderings are reported, never a failure
#   scripts/bench.sh paper3_sweeps   # paper 3's Tables 2-9 on rigs/cell.yaml (occupancy
#                                    # --sweep paper3, 32 mappers, 480 frames; issue 36: under
#                                    # 10 minutes here, checked), beside paper 3's numbers
#   scripts/bench.sh studio_latency  # issue 37: a pose change in `serve` to the numbers drawn and
#                                    # to the next frame, every bundled rig, headless Chromium
#   scripts/bench.sh localize_frozen # the frozen validation set (a second generator, seeds
#                                    # fixed before tuning; issue 33): report, never tune
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
only="${1:-}"
"$root/scripts/setup.sh" >&2
if [ -z "$only" ] || [ "$only" = "filters" ]; then "$root/scripts/install-pcl.sh" >&2; fi
build="$root/build/bench"
. "$root/scripts/ninja_build_dir.sh"
ninja_build_dir "$build"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRIGDESIGN_BUILD_TESTS=OFF \
  -DRIGDESIGN_BUILD_BENCHMARKS=ON -DRIGDESIGN_UNITY_BUILD=ON >/dev/null
cmake --build "$build" -j"$(nproc)" >/dev/null
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)," \
  "load average before the run: $(cut -d' ' -f1-3 /proc/loadavg)"
for bench in "$build"/tests/bench/*_bench; do
  name="$(basename "$bench" _bench)"
  case "$name" in
    filters_vs_pcl | filters_scaling)  # plain tables, no Google Benchmark
      if [ -z "$only" ] || [ "$only" = "filters" ]; then "$bench"; fi ;;
    occupancy_vs_octomap)
      if [ -z "$only" ] || [ "$only" = "occupancy" ]; then "$bench"; fi ;;
    *)
      if [ -z "$only" ] || [ "$only" = "$name" ]; then "$bench" --benchmark_format=console; fi ;;
  esac
done
if [ -z "$only" ] || [ "$only" = "paper2_table1" ]; then
  # Reports how many of paper 2's four orderings came out, and never fails on them (issue 54:
  # a benchmark that gates on a paper's answer invites tuning the scene until it passes). It
  # fails only when the run itself does.
  table_out="$(mktemp -d)"
  (cd "$root" && "$build/src/rigdesign" costmap rigs/elektron.yaml --scenario office_goals \
    --variants --seeds 20 --local-planner dwa --out "$table_out/costmap") | tee "$table_out/table.txt"
  holds="$(grep -c ': holds (' "$table_out/table.txt" || true)"
  rm -rf "$table_out"
  echo "paper2_table1: $holds of paper 2's 4 orderings hold on these 20 seeds (reported, not gated)"
fi
if [ -z "$only" ] || [ "$only" = "paper3_sweeps" ]; then
  started=$(date +%s)
  (cd "$root" && RIGDESIGN_PROGRESS=1 "$build/src/rigdesign" occupancy rigs/cell.yaml \
    --sweep paper3 --threads 2)
  seconds=$(( $(date +%s) - started ))
  echo "paper3_sweeps: ${seconds} s (target < 600 s)"
  if [ "$seconds" -ge 600 ]; then
    echo "paper3_sweeps: took ${seconds} s, over the 10-minute target" >&2
    exit 1
  fi
fi
if [ -z "$only" ] || [ "$only" = "localize_matrix" ]; then
  for seed in 1 2; do
    python3 "$root/scripts/localize/matrix_benchmark.py" "$build/src/rigdesign" \
      --runs-per-path 50 --seed "$seed"
  done
fi
if [ -z "$only" ] || [ "$only" = "localize_frozen" ]; then
  python3 "$root/scripts/localize/frozen_benchmark.py" "$build/src/rigdesign"
fi
if [ -z "$only" ] || [ "$only" = "studio_latency" ]; then
  python3 "$root/tests/bench/studio_latency.py" "$build/src/rigdesign" "$root"
fi
echo "load average after the run: $(cut -d' ' -f1-3 /proc/loadavg)"
