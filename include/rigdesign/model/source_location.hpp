#pragma once
#include <string>

namespace rigdesign::model {

/// Where a value came from in an input file, so findings can point at it. Lines and columns
/// are 1-based, as editors and compilers show them; 0 means "the whole file".
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

/// "file:line:col", "file:line" when the column is unknown (XML), or "file" for the whole file.
std::string to_string(const SourceLocation& where);

}  // namespace rigdesign::model
