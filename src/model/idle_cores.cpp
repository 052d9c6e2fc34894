#include "rigdesign/model/idle_cores.hpp"

#include <sched.h>

#include <algorithm>
#include <fstream>
#include <string>

namespace rigdesign::model {

int idle_cores() {
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (sched_getaffinity(0, sizeof(allowed), &allowed) != 0) return 0;
  const int cores = CPU_COUNT(&allowed);
  // /proc/loadavg: "0.52 0.58 0.59 2/511 12345"; the fourth field is runnable/total threads,
  // the runnable ones including the caller.
  std::ifstream loadavg("/proc/loadavg");
  std::string one, five, fifteen, threads;
  if (!(loadavg >> one >> five >> fifteen >> threads)) return 0;
  const std::size_t slash = threads.find('/');
  if (slash == std::string::npos) return 0;
  int runnable = 0;
  try {
    runnable = std::stoi(threads.substr(0, slash));
  } catch (const std::exception&) {
    return 0;
  }
  return std::max(0, cores - std::max(1, runnable));
}

}  // namespace rigdesign::model
