#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, AddressSanitizer + UndefinedBehaviorSanitizer) and runs
# them on seed corpora made from the bundled files (docs/fuzzing.md).
#   scripts/fuzz.sh                      # list the targets
#   scripts/fuzz.sh TARGET [SECONDS [RUNS]]  # one campaign (default 600 s, or until RUNS
#                                        # executions if sooner); the corpus grows in
#                                        # build/fuzz/corpus/TARGET and is kept between runs
#   scripts/fuzz.sh --all [SECONDS]      # every target of rigdesign's own readers for SECONDS
#                                        # each (default 15), two at a time: what CI runs.
#                                        # Exit 1 on any finding.
# A finding (crash, leak, undefined behaviour, timeout, out-of-memory, an uncaught exception or
# an error message without a file) leaves its input in build/fuzz/findings/.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build/fuzz"
own_targets=(rig_yaml rig_text_edit sensors_yaml requirements_yaml catalog_yaml policy_yaml scene_yaml scenario_yaml
  pipeline_yaml costmap_params_yaml filtering_loads_yaml artifacts_json clearpath_robot_yaml
  collision_monitor_yaml
  cloud_pcd cloud_ply
  mesh_obj mesh_off mesh_ply robot_urdf robot_xacro export_writers rssi_csv co2_csv
  emitter_truth_csv walls_csv
  map_pgm studio_router)
# Formats parsed by assimp: rigdesign only checks what comes out. assimp 5.2's own parsers
# allocate without bound on some corrupt COLLADA files (docs/fuzzing.md), so these run in
# campaigns (scripts/fuzz.sh mesh_dae 600), not in CI, where they would fail at random.
assimp_targets=(mesh_stl mesh_dae)
targets=("${own_targets[@]}" "${assimp_targets[@]}")

if [ $# -eq 0 ]; then
  printf '%s\n' "${targets[@]}"
  exit 0
fi

# Bundled files that seed each target, beside the synthetic ones of fuzz/make_seeds.py. Files
# over the fuzzer's maximum input length are left out: mutating megabytes is slow.
bundled_seeds() {
  cd "$root"
  case "$1" in
    rig_yaml|rig_text_edit) ls rigs/*.yaml ;;
    sensors_yaml) echo sensors.yaml ;;
    requirements_yaml) ls rigs/requirements/*.yaml ;;
    catalog_yaml) ls rigs/catalogs/*.yaml ;;
    policy_yaml) ls rigs/policies/*.yaml ;;
    scene_yaml) ls rigs/scenes/*/*.yaml | grep -v "\.scenario\.yaml$" ;;
    scenario_yaml) ls rigs/scenes/*/*.scenario.yaml ;;
    costmap_params_yaml) ls rigs/costmap/*.yaml ;;
    clearpath_robot_yaml) ls tests/data/clearpath/*.yaml ;;
    collision_monitor_yaml) ls tests/data/collision_monitor/*.yaml ;;
    mesh_obj) ls rigs/scenes/*/*.obj ;;
    mesh_off) ls rigs/scenes/*/*.off ;;
    mesh_ply) ls rigs/scenes/*/*.ply ;;
    mesh_stl) find rigs/robots -name '*.stl' -size -64k ;;
    mesh_dae) find rigs/robots -name '*.dae' -size -64k ;;
    robot_urdf) find rigs -name '*.urdf' ;;
    robot_xacro) find rigs/robots -name '*.xacro' -size -64k ;;
    rssi_csv) ls data/localize/*_rssi.csv ;;
    emitter_truth_csv) ls data/localize/*_truth.csv ;;
  esac
}

dictionary_of() {
  case "$1" in
    *_yaml | artifacts_json | rig_text_edit) echo yaml ;;
    cloud_pcd) echo pcd ;;
    cloud_ply | mesh_ply) echo ply ;;
    mesh_obj) echo obj ;;
    mesh_off) echo off ;;
    mesh_stl) echo stl ;;
    mesh_dae | robot_urdf | robot_xacro | export_writers) echo xml ;;
    *_csv) echo csv ;;
    map_pgm) echo pgm ;;
    studio_router) echo http ;;
  esac
}

build_fuzzers() {
  "$root/scripts/setup.sh" >&2
  . "$root/scripts/ninja_build_dir.sh"
  ninja_build_dir "$build"
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DRIGDESIGN_FUZZ=ON -DRIGDESIGN_BUILD_TESTS=OFF -DRIGDESIGN_WERROR=ON \
    -DRIGDESIGN_UNITY_BUILD=ON >/dev/null
  cmake --build "$build" --target rigdesign_fuzzers -j"$(nproc)" >&2
  python3 "$root/fuzz/make_seeds.py" "$build/seeds" >&2
}

# run_target TARGET SECONDS [RUNS]: one libFuzzer run; prints "TARGET executions exec/s result".
run_target() {
  local target="$1" seconds="$2" runs_limit="${3:--1}"
  local corpus="$build/corpus/$target" seeds="$build/seeds/$target"
  mkdir -p "$corpus" "$seeds" "$build/findings" "$build/logs"
  while IFS= read -r file; do
    [ -n "$file" ] && cp "$root/$file" "$seeds/$(echo "$file" | tr / _)"
  done < <(bundled_seeds "$target")
  local log="$build/logs/$target.log" status=0 max_len
  # Longest input per format. Execution time grows with the input: at 64 KiB a CSV log ran at
  # 1,000 exec/s, too slow for a million executions. What a reader can get wrong is local (one
  # entry, one field, one header line) or driven by a count the header states, so short
  # inputs find it: one sensor or mount entry is well under 1 KiB (sensors.yaml is 28 KiB);
  # binary clouds keep room for a few hundred points. Seeds are cut to the limit.
  case "$(dictionary_of "$target")" in
    yaml) max_len=2048 ;;
    csv | pgm | http) max_len=4096 ;;
    xml) max_len=8192 ;;
    *) max_len=65536 ;;
  esac
  # Leaks are findings; -timeout: one input may take 10 s under the sanitizers; -rss_limit_mb:
  # a reader that believes a header's count and allocates gigabytes is a finding too.
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$build/fuzz/fuzz_$target" "$corpus" "$seeds" -dict="$root/fuzz/dictionaries/$(dictionary_of "$target").dict" \
    -max_total_time="$seconds" -runs="$runs_limit" -timeout=10 -rss_limit_mb=2048 -max_len="$max_len" \
    -print_final_stats=1 -artifact_prefix="$build/findings/$target-" >"$log" 2>&1 || status=$?
  local runs rate
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  if [ "$status" -eq 0 ]; then
    printf '%-22s %10s executions %7s exec/s  ok\n' "$target" "${runs:-?}" "${rate:-?}"
  else
    printf '%-22s %10s executions %7s exec/s  FINDING (log: %s)\n' "$target" "${runs:-?}" \
      "${rate:-?}" "$log"
    grep -m3 -E 'ERROR|SUMMARY|finding|terminate' "$log" | sed 's/^/    /'
    return 1
  fi
}

if [ "$1" = "--all" ]; then
  seconds="${2:-15}"
  build_fuzzers
  echo "fuzz.sh: the targets built in $SECONDS s" >&2
  export -f run_target bundled_seeds dictionary_of
  export root build
  printf '%s\n' "${own_targets[@]}" |
    xargs -P"$(nproc)" -I{} bash -c 'run_target "$1" "$2"' _ {} "$seconds"
  exit $?
fi

target="$1"
if ! printf '%s\n' "${targets[@]}" | grep -qx "$target"; then
  echo "fuzz.sh: unknown target '$target' (scripts/fuzz.sh lists them)" >&2
  exit 2
fi
build_fuzzers
run_target "$target" "${2:-600}" "${3:--1}"
