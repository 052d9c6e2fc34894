#include "rigdesign/model/ros_names.hpp"

#include <cctype>

namespace rigdesign::model {
namespace {

bool is_token(const std::string& token) {
  if (token.empty() || std::isdigit(static_cast<unsigned char>(token.front()))) return false;
  for (const char c : token) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  }
  return true;
}

}  // namespace

bool is_topic_name(const std::string& name) {
  std::size_t start = !name.empty() && name.front() == '/' ? 1 : 0;
  if (start >= name.size()) return false;
  while (true) {
    const std::size_t slash = name.find('/', start);
    if (!is_token(name.substr(start, slash - start))) return false;
    if (slash == std::string::npos) return true;
    start = slash + 1;
  }
}

bool is_frame_id(const std::string& name) {
  if (name.empty() || name.front() == '/') return false;
  for (const char c : name) {
    if (c <= ' ' || c >= 0x7f || c == '"' || c == '\'' || c == '\\' || c == '#' || c == ':')
      return false;
  }
  return true;
}

}  // namespace rigdesign::model
