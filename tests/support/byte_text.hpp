#pragma once
// Test helper: a value's bytes in memory order, for building binary files (PCD, PLY, STL) by hand.
#include <cstring>
#include <string>

namespace rigdesign::test {

template <typename T>
std::string bytes_of(T value) {
  std::string bytes(sizeof value, '\0');
  std::memcpy(bytes.data(), &value, sizeof value);
  return bytes;
}

}  // namespace rigdesign::test
