#pragma once
// What a measured time was measured on, for reports: timings are only comparable on one
// machine, so the loads file and the filter report name it.
#include <string>

namespace rigdesign::cli {

/// "N cores, <CPU model name>, one thread" from /proc/cpuinfo.
std::string describe_machine();

/// The process's peak resident memory [MiB].
double peak_memory_mib();

}  // namespace rigdesign::cli
