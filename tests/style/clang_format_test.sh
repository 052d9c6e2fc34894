#!/usr/bin/env bash
# Every C++ file of the project is as .clang-format lays it out (issue 51 item 7): lists the
# files clang-format would change and fails if there is one. Fix with clang-format -i FILE.
# One clang-format process per 100 files: a process per file took 23 s of CI's test time.
#   clang_format_test.sh SOURCE_ROOT [CLANG_FORMAT]
set -euo pipefail
root="$1"
clang_format="${2:-clang-format}"
cd "$root"
mapfile -d '' files < <(find src include tests fuzz -type f \
  \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' \) -not -path 'tests/layering/fixture/*' \
  -print0 | sort -z)
# --dry-run -Werror reports "FILE:LINE:COL: error: code should be clang-formatted" per change.
unformatted="$(printf '%s\0' "${files[@]}" |
  xargs -0 -n 100 "$clang_format" --dry-run -Werror 2>&1 >/dev/null |
  sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' | sort -u || true)"
count=0
if [ -n "$unformatted" ]; then
  count="$(printf '%s\n' "$unformatted" | wc -l)"
  printf 'not clang-formatted: %s\n' $unformatted
fi
echo "clang-format: $count of ${#files[@]} files not formatted"
[ "${#files[@]}" -gt 0 ] && [ "$count" -eq 0 ]
