#include "rigdesign/model/source_location.hpp"

namespace rigdesign::model {

std::string to_string(const SourceLocation& where) {
  if (where.line <= 0) return where.file;
  return where.file + ":" + std::to_string(where.line) + ":" + std::to_string(where.column);
}

}  // namespace rigdesign::model
