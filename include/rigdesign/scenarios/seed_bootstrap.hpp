#pragma once
/// How sure paper 2's Table 1 is of its orderings (issue 54): a bootstrap over seeds. Each
/// seed is one office layout, one noise stream and one set of frame phases, the same for
/// every rig variant; resampling the seeds with replacement and recomputing each variant's
/// critical distance and average speed on the same resample gives paired intervals for the
/// differences between variants.
#include <cstdint>
#include <vector>

#include "rigdesign/scenarios/variant_sweep.hpp"

namespace rigdesign::scenarios {

/// `rounds` resamples of `count` seed indices drawn with replacement from a std::mt19937_64
/// seeded with `seed` (deterministic).
std::vector<std::vector<std::size_t>> seed_resamples(std::size_t count, int rounds,
                                                     std::uint64_t seed);

/// The critical distance [m] of the seeds `picked` (indices into the variant's seeds): the
/// first of `margins` at which none of them collided (outcome.collided_by_margin); infinity
/// when they collided at every margin run.
double resampled_critical_distance(const VariantOutcome& outcome,
                                   const std::vector<double>& margins,
                                   const std::vector<std::size_t>& picked);

/// The average speed [m/s] of the seeds `picked`, pooled over their runs at the table's margin
/// (means_of); the runs must hold one per seed, in seed order.
double resampled_average_speed(const VariantOutcome& outcome,
                               const std::vector<std::size_t>& picked);

struct Interval {
  double low = 0.0;
  double high = 0.0;
};

/// The central `level` interval of `values` by nearest rank: the values at ranks
/// ceil(n (1 - level) / 2) and ceil(n (1 + level) / 2), from 1. Throws std::invalid_argument
/// for no values or a level outside (0, 1).
Interval percentile_interval(std::vector<double> values, double level = 0.95);

}  // namespace rigdesign::scenarios
