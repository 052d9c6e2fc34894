# Sourced by the scripts that configure a build folder. Ninja schedules every object file of
# every library at once, where Make builds a library's objects only after the libraries it
# links (a chain of 15 modules that left a core idle), and it starts faster on a rebuild.
# A folder configured by another generator is configured afresh (CMake refuses to switch).
ninja_build_dir() {
  local build="$1"
  if [ -f "$build/CMakeCache.txt" ] &&
    ! grep -q '^CMAKE_GENERATOR:INTERNAL=Ninja$' "$build/CMakeCache.txt"; then
    echo "$(basename "$0"): $build was made with another generator: configuring it for Ninja" >&2
    rm -rf "$build/CMakeCache.txt" "$build/CMakeFiles"
  fi
}
