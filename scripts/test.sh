#!/usr/bin/env bash
# Sets up, builds with AddressSanitizer and UndefinedBehaviorSanitizer (warnings are errors)
# and runs the whole ctest suite.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# Each phase's wall time goes to standard error (CI's budget is 25 minutes; docs/development.md).
phase_start=$SECONDS
phase_done() {
  echo "test.sh: $1 took $((SECONDS - phase_start)) s" >&2
  phase_start=$SECONDS
}
"$root/scripts/setup.sh"
phase_done setup
build="$root/build/sanitize"
. "$root/scripts/ninja_build_dir.sh"
ninja_build_dir "$build"
# -O1 -g1: the optimisation AddressSanitizer's documentation recommends and line tables for
# its reports; compiles about 40 % faster than -O2 -g (CI's build was 27 of its 32 minutes).
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRIGDESIGN_SANITIZE=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DRIGDESIGN_WERROR=ON -DRIGDESIGN_BUILD_TESTS=ON -DRIGDESIGN_UNITY_BUILD=ON
cmake --build "$build" -j"$(nproc)"
phase_done build
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir "$build" --output-on-failure -j"$(nproc)"
phase_done ctest
# Every reader of user files under libFuzzer (clang, ASan + UBSan) for 5 s each (longer
# campaigns: scripts/fuzz.sh TARGET SECONDS):
# any crash, leak, undefined behaviour, timeout or unclear error fails the run (docs/fuzzing.md).
"$root/scripts/fuzz.sh" --all 5
phase_done fuzz
