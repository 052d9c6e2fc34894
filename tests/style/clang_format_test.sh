#!/usr/bin/env bash
# Every C++ file of the project is as .clang-format lays it out (issue 51 item 7): lists the
# files clang-format would change and fails if there is one. Fix with clang-format -i FILE.
#   clang_format_test.sh SOURCE_ROOT [CLANG_FORMAT]
set -euo pipefail
root="$1"
clang_format="${2:-clang-format}"
cd "$root"
unformatted=0
checked=0
while IFS= read -r -d '' file; do
  checked=$((checked + 1))
  if ! "$clang_format" --dry-run -Werror "$file" >/dev/null 2>&1; then
    echo "not clang-formatted: $file"
    unformatted=$((unformatted + 1))
  fi
done < <(find src include tests fuzz -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' \) \
           -not -path 'tests/layering/fixture/*' -print0 | sort -z)
echo "clang-format: $unformatted of $checked files not formatted"
[ "$checked" -gt 0 ] && [ "$unformatted" -eq 0 ]
