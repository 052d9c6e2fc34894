#!/usr/bin/env bash
# Runs the outputs a restructuring must keep byte for byte with one rigdesign binary, into a
# folder: the main job's files, `metrics` (text and JSON) and `coverage` of every bundled rig, `export`
# of every bundled rig and `check --format junit` of them all. Run it with the binary before
# and after a change and diff the two folders (`diff -r`); timing fields are blanked first.
#   scripts/same-outputs.sh BINARY OUTPUT_FOLDER
set -euo pipefail
binary="$(realpath "$1")"
out="$(realpath -m "$2")"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
rm -rf "$out"
mkdir -p "$out"
# Seconds and machine descriptions differ from run to run; everything else must not.
blank_times() {
  sed -E -e 's/[0-9]+\.[0-9]+ s\b/T s/g' -e 's/"(seconds|time|elapsed_s|search_seconds|[a-z_]*_seconds)": *[0-9.e+-]+/"\1": T/g' \
         -e 's/time="[0-9.]+"/time="T"/g' -e 's/timestamp="[^"]*"/timestamp="T"/g'
}
"$binary" select --catalog rigs/catalogs/ur_cleaner.yaml \
  --requirements rigs/requirements/ur_cleaner.yaml --policy rigs/policies/ur_cleaner.yaml \
  --budget 3000 --out "$out/main_job" 2>/dev/null | blank_times >"$out/main_job.stdout" || true
for rig in rigs/*.yaml; do
  name="$(basename "$rig" .yaml)"
  "$binary" metrics "$rig" --json 2>/dev/null | blank_times >"$out/metrics_$name.json" || true
  "$binary" metrics "$rig" 2>/dev/null | blank_times >"$out/metrics_$name.txt" || true
  "$binary" coverage "$rig" --out "$out/coverage_$name" >/dev/null 2>&1 || true
  "$binary" export "$rig" --to "$out/export_$name" >/dev/null 2>&1 || true
done
for requirements in rigs/requirements/*.yaml; do
  name="$(basename "$requirements" .yaml)"
  "$binary" metrics rigs/ur_cleaner.yaml --requirements "$requirements" 2>/dev/null |
    blank_times >"$out/metrics_ur_cleaner_against_$name.txt" || true
done
"$binary" check rigs/*.yaml --format junit 2>/dev/null | blank_times >"$out/check.junit.xml" || true
# Files whose text carries timings get the same blanking.
find "$out" -type f \( -name '*.json' -o -name '*.csv' -o -name '*.yaml' -o -name '*.txt' \) -print0 |
  while IFS= read -r -d '' file; do blank_times <"$file" >"$file.tmp" && mv "$file.tmp" "$file"; done
echo "outputs in $out"
