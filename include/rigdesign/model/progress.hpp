#pragma once
/// A long computation's report of how far it has got, for the CLI's progress line (the
/// library never prints). Called with work done so far and the total, in the caller's units.
#include <functional>

namespace rigdesign::model {

using ProgressCallback = std::function<void(double done, double total)>;

}  // namespace rigdesign::model
