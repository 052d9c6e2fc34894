# cmake -DOUTPUT=file.hpp -DNAMES="a|b" -DFILES="x|y" -P embed_text_files.cmake
# Writes a header defining `inline constexpr std::string_view NAME` holding each file's bytes,
# as hexadecimal escapes (any byte, no delimiter to collide with). The studio's page is
# compiled into the program this way, so `serve` needs no install path for it.
string(REPLACE "|" ";" NAMES "${NAMES}")
string(REPLACE "|" ";" FILES "${FILES}")
list(LENGTH NAMES count)
math(EXPR last "${count} - 1")
set(text "#pragma once\n// Generated from the studio's page files by cmake/embed_text_files.cmake.\n#include <string_view>\n\nnamespace rigdesign::studio {\n")
foreach(i RANGE ${last})
  list(GET NAMES ${i} name)
  list(GET FILES ${i} file)
  file(READ "${file}" hex HEX)
  string(LENGTH "${hex}" hex_length)
  math(EXPR bytes "${hex_length} / 2")
  string(REGEX REPLACE "([0-9a-f][0-9a-f])" "\\\\x\\1" escaped "${hex}")
  # Split into lines of 64 bytes so the literal stays readable by compilers and editors.
  string(REGEX REPLACE "((\\\\x[0-9a-f][0-9a-f]){64})" "\\1\"\n    \"" escaped "${escaped}")
  string(APPEND text "inline constexpr std::string_view ${name}(\n    \"${escaped}\", ${bytes});\n")
endforeach()
string(APPEND text "\n}  // namespace rigdesign::studio\n")
file(WRITE "${OUTPUT}" "${text}")
