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
#                                    # seeds in office_goals, paper 2's configuration and paper
#                                    # 1's, table seeds and held-out seeds, the critical-
#                                    # distance sweep included; the orderings are reported with
#                                    # bootstrap intervals, never a failure
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
  # Paper 2's Table 1 (issue 54 item 1) in two configurations, each on the table's seeds 1-20
  # and on held-out seeds 1001-1020 (fixed before the first run): paper 2's as its section 3
  # describes it (voxel layer, lidar marking only, DWA at 0.227 m/s, radius outlier removal),
  # and paper 1's costmap at 0.4 m/s (the labelled variant measured before). Reports how many
  # of paper 2's four orderings came out, each with its bootstrap interval, and never fails on
  # them (a benchmark that gates on a paper's answer invites tuning the scene until it
  # passes). It fails only when a run itself does.
  table_out="$(mktemp -d)"
  paper2=(--params rigs/costmap/elektron_paper2.yaml --local-planner dwa --speed 0.227
          --radius-outlier 0.05)
  paper1=(--local-planner dwa)
  for config in paper2 paper1; do
    for first in 1 1001; do
      if [ "$config" = paper2 ]; then options=("${paper2[@]}"); else options=("${paper1[@]}"); fi
      echo "== paper 2's Table 1, configuration $config, seeds $first to $((first + 19))"
      (cd "$root" && "$build/src/rigdesign" costmap rigs/elektron.yaml --scenario office_goals \
        "${options[@]}" --variants --seed "$first" --seeds 20 --frame-every 0 \
        --out "$table_out/$config-$first") | tee "$table_out/table.txt"
      holds="$(grep -c ': holds (' "$table_out/table.txt" || true)"
      echo "paper2_table1 ($config, seeds $first-$((first + 19))): $holds of paper 2's 4" \
        "orderings hold (reported, not gated)"
    done
  done
  rm -rf "$table_out"
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
