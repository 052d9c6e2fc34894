#pragma once
/// What `select` says while it runs and after it (issue 32): every phase (search, exact
/// verification, pose refinement, robustness cost, binding requirements, renders) with its
/// own count, so a progress line estimates the time left from that phase's own rate, and a
/// summary line per phase of what ran and how long.
#include <chrono>
#include <functional>
#include <string>
#include <vector>

namespace rigdesign::select {

struct PhaseProgress {
  std::string phase;   ///< "search", "exact verification", ...
  double done = 0.0;   ///< of `total` `unit`s
  double total = 0.0;  ///< 1 when `done` is a share (a search tree's estimated fraction)
  std::string unit;    ///< what is counted ("coverages", "rigs"); "" for a share
  std::string detail;  ///< for a share, shown instead of the count ("97935 nodes")
  /// The phase has ended: `detail` says what it did, `seconds` how long it took.
  bool finished = false;
  double seconds = 0.0;
};
using ProgressSink = std::function<void(const PhaseProgress&)>;

/// A phase that ran: what it did and how long it took.
struct PhaseTime {
  std::string phase;
  std::string work;  ///< "97935 nodes, 60244 rigs evaluated"
  double seconds = 0.0;
};

/// Appends a PhaseTime to `log` per start() ... stop() pair, and tells `progress` (if any)
/// that the phase ended.
class PhaseClock {
 public:
  explicit PhaseClock(std::vector<PhaseTime>& log, const ProgressSink* progress = nullptr)
      : log_(log), progress_(progress) {}
  void start(std::string phase) {
    phase_ = std::move(phase);
    started_ = std::chrono::steady_clock::now();
  }
  void stop(std::string work) {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    if (progress_ != nullptr && *progress_)
      (*progress_)({phase_, 1.0, 1.0, "", work, true, seconds});
    log_.push_back({std::move(phase_), std::move(work), seconds});
  }

 private:
  std::vector<PhaseTime>& log_;
  const ProgressSink* progress_;
  std::string phase_;
  std::chrono::steady_clock::time_point started_;
};

}  // namespace rigdesign::select
