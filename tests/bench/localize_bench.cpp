// Paper 4's speed figures against ours (DESIGN.md section 8: 4,000 measurements in
// 360-433 ms, 16,000 in 1.4-1.9 s on an i7-8th gen, for the linear method). Logs are the
// synthetic `loop` scenario read at a scan rate that yields N readings. Counters: time per
// reading for the O(1) update of paper 4's system (constant across N), and the full solves.
#include <benchmark/benchmark.h>

#include "rigdesign/localize/emitter_localizer.hpp"
#include "rigdesign/localize/log_generator.hpp"
#include "rigdesign/localize/wls_multilateration.hpp"

namespace {

using namespace rigdesign;

// The loop scenario (about 1,700 readings at 10 Hz) read faster, cut to `readings`.
localize::RssiLog loop_log(std::size_t readings) {
  localize::ScenarioParams params;
  params.scan_rate = 10.0 * static_cast<double>(readings) / 1500.0;
  localize::RssiLog log = localize::make_scenario("loop", params).log;
  log.readings.resize(std::min(readings, log.readings.size()));
  return log;
}

// Paper 4's online method: add a reading and re-solve, per reading.
void BM_WlsUpdatePerReading(benchmark::State& state) {
  const localize::RssiLog log = loop_log(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    localize::IncrementalWls wls;
    for (const localize::RssiReading& r : log.readings) {
      wls.add(r.position, r.rssi_dbm);
      benchmark::DoNotOptimize(wls.solve(2));
    }
  }
  state.counters["readings"] = static_cast<double>(log.readings.size());
  state.counters["per_reading"] = benchmark::Counter(
      static_cast<double>(log.readings.size()),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void full_solve(benchmark::State& state, localize::LocalizeMethod method) {
  const localize::RssiLog log = loop_log(static_cast<std::size_t>(state.range(0)));
  std::size_t chunks = 0;
  for (auto _ : state) {
    const localize::EmitterEstimate estimate = localize::localize_emitter(log, 0, method);
    chunks = estimate.chunks.size();
    benchmark::DoNotOptimize(estimate.hypotheses.data());
  }
  state.counters["readings"] = static_cast<double>(log.readings.size());
  state.counters["chunks"] = static_cast<double>(chunks);
}

// Chunking plus one solve over the whole log.
void BM_WlsFullSolve(benchmark::State& state) {
  full_solve(state, localize::LocalizeMethod::wls);
}
void BM_RangeFitFullSolve(benchmark::State& state) {
  full_solve(state, localize::LocalizeMethod::nls);
}
void BM_ObjectMapFullSolve(benchmark::State& state) {
  full_solve(state, localize::LocalizeMethod::map);
}

BENCHMARK(BM_WlsUpdatePerReading)->Arg(1000)->Arg(4000)->Arg(16000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WlsFullSolve)->Arg(4000)->Arg(16000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RangeFitFullSolve)->Arg(4000)->Arg(16000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ObjectMapFullSolve)->Arg(4000)->Arg(16000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
