#!/usr/bin/env bash
# Installs the build to a temporary prefix, moves the prefix, and runs the moved binary from
# another folder: it must find its bundled sensor library beside itself (share/rigdesign), not
# through any path of the build. The same prefix is a ROS 2 package prefix: ament_index_python
# (Debian's python3-ament-index, what `ros2 pkg prefix` calls) finds rigdesign in it and its
# share folder is the one the binary reads; colcon (Debian's) takes the source tree for a
# ros.cmake package. Usage: relocated_install_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build="$1"
source_dir="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$work/first" >/dev/null
mv "$work/first" "$work/moved"
prefix="$work/moved"
[ -x "$prefix/bin/rigdesign" ] || fail "no bin/rigdesign in the prefix"
[ -f "$prefix/share/rigdesign/sensors.yaml" ] || fail "no share/rigdesign/sensors.yaml"
[ -f "$prefix/share/rigdesign/rigs/robots/SOURCES.md" ] || fail "robot licence notices not installed"

# A user's rig in a folder with no sensors.yaml above it: the bundled library is the fallback.
mkdir "$work/elsewhere"
cp "$prefix/share/rigdesign/rigs/delivery_amr.yaml" "$work/elsewhere/"
cd "$work/elsewhere"
out="$("$prefix/bin/rigdesign" metrics delivery_amr.yaml)" || fail "metrics exited $?"
grep -qF "sensors from $prefix/share/rigdesign/sensors.yaml" <<<"$out" \
  || fail "library not found beside the moved binary: $(head -1 <<<"$out")"
# Sensor cost from the library's text: Livox Mid-360 560 + RealSense D455 419 + Hokuyo
# UST-10LX 1600 USD.
grep -qE "C_s = 2579 USD" <<<"$out" || fail "sensor cost is not 2579 USD"

# A bundled rig that reaches its robot description through a relative path, run from here.
"$prefix/bin/rigdesign" metrics "$prefix/share/rigdesign/rigs/turtlebot4.yaml" >/dev/null \
  || fail "bundled turtlebot4 rig did not run from the moved prefix"

# $RIGDESIGN_DATA_DIR wins; a folder without a library is a clear input error (exit 2).
mkdir "$work/empty"
set +e
RIGDESIGN_DATA_DIR="$work/empty" "$prefix/bin/rigdesign" metrics delivery_amr.yaml \
  >/dev/null 2>"$work/error.txt"
status=$?
set -e
[ "$status" -eq 2 ] || fail "missing library: exit $status, expected 2"
grep -qF "$work/empty/sensors.yaml" "$work/error.txt" || fail "error does not name the path"
grep -qF "RIGDESIGN_DATA_DIR" "$work/error.txt" || fail "error does not name the variable"
# The ament index: an empty marker file names the package; its share folder holds package.xml
# and the data the binary reads.
[ -f "$prefix/share/ament_index/resource_index/packages/rigdesign" ] || fail "no ament index marker"
[ -f "$prefix/share/rigdesign/package.xml" ] || fail "no share/rigdesign/package.xml"
found="$(AMENT_PREFIX_PATH="$prefix" ament_index packages rigdesign)" \
  || fail "ament_index does not find rigdesign in $prefix"
[ "$found" = "$prefix" ] || fail "ament_index gives '$found', expected $prefix"
share="$(AMENT_PREFIX_PATH="$prefix" /usr/bin/python3 -c \
  'from ament_index_python.packages import get_package_share_directory as s; print(s("rigdesign"))')"
[ "$share/sensors.yaml" = "$prefix/share/rigdesign/sensors.yaml" ] \
  || fail "ament's share folder $share is not where the binary reads its library"
# colcon's hook that puts the prefix on AMENT_PREFIX_PATH (named in colcon.pkg) is installed.
hook="$(/usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["hooks"][0])' \
  "$source_dir/colcon.pkg")"
[ -f "$prefix/$hook" ] || fail "colcon.pkg names $hook, which is not installed"
grep -qx 'prepend-non-duplicate;AMENT_PREFIX_PATH;' "$prefix/$hook" || fail "$hook does not add the prefix"

# colcon identifies the source tree as a ROS package of build type cmake (package.xml parsed
# by catkin_pkg: a malformed manifest falls back to plain cmake with a warning).
listed="$(cd "$work" && colcon --log-base /dev/null list --base-paths "$source_dir" 2>&1)"
grep -qP '^rigdesign\t.*\(ros\.cmake\)$' <<<"$listed" || fail "colcon list: $listed"
grep -q WARNING <<<"$listed" && fail "colcon warns: $listed"
echo "relocated install: ok"
