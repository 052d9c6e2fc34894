#include "rigdesign/model/source_location.hpp"

namespace rigdesign::model {

std::string to_string(const SourceLocation& where) {
  if (where.line <= 0) return where.file;
  const std::string line = where.file + ":" + std::to_string(where.line);
  return where.column > 0 ? line + ":" + std::to_string(where.column) : line;
}

}  // namespace rigdesign::model
