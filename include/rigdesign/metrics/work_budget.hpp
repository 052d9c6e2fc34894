#pragma once
/// A long computation's limits and its progress (issue 53 item 3): `check` on a rig with a
/// six-axis tolerance on every mount judges hundreds of moved rigs, each a whole exact
/// coverage cut. The work reports how far it is, and stops with a clear error naming the
/// option once it has run `max_seconds`, saying how much more it needed.
#include <chrono>
#include <functional>
#include <limits>
#include <string>

namespace rigdesign::metrics {

struct WorkBudget {
  /// [s] from `started`; infinity: no limit.
  double max_seconds = std::numeric_limits<double>::infinity();
  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
  /// The command-line option that set max_seconds, named by the error.
  std::string option = "--max-seconds";
  /// Called with (done, total) after each piece of work, from one thread at a time.
  std::function<void(double, double)> progress;

  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  }
  /// Throws model::InputError naming `option` when the time is up: `done` of `total` pieces
  /// of `what` were judged, and the rest would take about as long each.
  void check_time(double done, double total, const std::string& what) const;
};

}  // namespace rigdesign::metrics
