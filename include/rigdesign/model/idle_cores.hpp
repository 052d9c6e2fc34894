#pragma once
/// How many more threads a computation can start without taking a core from other work (the
/// statistical outlier filter's neighbour queries, the range fit's posterior grid).
//
// Why: on a robot computer the other core is often busy (drivers, planners); a second filter
// thread then only time-slices with that work and measured no faster, sometimes slower
// (scripts/bench.sh filters, "threads"). Asking the kernel how many threads are runnable now
// is cheap (one read of /proc/loadavg, microseconds beside a SOR pass of milliseconds).

namespace rigdesign::model {

/// Cores this process may use that no runnable thread occupies now, not counting the caller's
/// own; 0 when it cannot tell (no /proc).
int idle_cores();

}  // namespace rigdesign::model
