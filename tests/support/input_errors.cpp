#include "input_errors.hpp"

#include <catch2/catch.hpp>

#include "rigdesign/model/input_error.hpp"

namespace rigdesign::test {

std::string input_error_of(const std::function<void()>& run) {
  try {
    run();
  } catch (const model::InputError& error) {
    UNSCOPED_INFO(error.what());  // shown when a check on the message fails
    return error.what();
  }
  return "";
}

}  // namespace rigdesign::test
