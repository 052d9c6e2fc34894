#pragma once
// What a loader says when it refuses its input, for tests that check the message.
#include <functional>
#include <string>

namespace rigdesign::test {

/// The InputError message `run` throws (also logged for a failing check), or "" when it
/// throws none. Other exceptions pass through: they are failures of their own.
std::string input_error_of(const std::function<void()>& run);

}  // namespace rigdesign::test
