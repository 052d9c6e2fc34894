#include "posterior_search.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>

#include "rigdesign/model/idle_cores.hpp"
#include "rigdesign/model/parallel_for.hpp"

namespace rigdesign::localize::detail {
namespace {

constexpr double kUnevaluated = -std::numeric_limits<double>::infinity();

struct Level {
  double cell;            // [m]
  bool half_metre;        // the scans merged at 0.5 m (else 1 m)
  double keep;            // cells within this of the best (log) are refined at the next level
  std::size_t max_cells;  // a finer grid would need more cells: stop refining here
};

// Coarse cells can sit a few metres from a sharp peak, so the first band is wide. A posterior
// broad enough to need many 0.25 m cells is drawn well enough at 0.5 m: the last level is only
// for narrow ones. Scans merged at 1 m and 0.5 m move distances of a few metres by centimetres.
constexpr Level kLevels[] = {
    {2.0, false, 20.0, 0}, {1.0, false, 12.0, 60000}, {0.5, true, 0.0, 20000}};
constexpr int kMaxCoarseCells = 60;        // per axis: wider boxes get coarser first cells
constexpr std::size_t kRefinedMaxima = 8;  // coarse local maxima always refined

struct Grid {
  model::Vec2 origin = model::Vec2::Zero();
  double cell = 1.0;
  int columns = 0, rows = 0;
  std::vector<double> value;  // log density, kUnevaluated where not evaluated

  model::Vec2 centre(int c, int r) const { return origin + cell * model::Vec2(c + 0.5, r + 0.5); }
  double& at(int c, int r) { return value[static_cast<std::size_t>(r * columns + c)]; }
  double at(int c, int r) const { return value[static_cast<std::size_t>(r * columns + c)]; }
};

// The profile log density at the centres of `cells` (indices into grid->value). The grid's
// points are independent, and they are most of the range fit's time: chunks of them go to this
// thread and, when a core is idle, to helpers (each point's value is the same whichever thread
// computes it, so the result does not depend on the number of threads).
void evaluate_cells(const CensoredLikelihood& likelihood, const std::vector<int>& cells,
                    Grid* grid) {
  constexpr std::size_t kChunk = 64;
  constexpr std::size_t kMaxThreads = 4;
  std::size_t threads = std::min(kMaxThreads, cells.size() / (4 * kChunk) + 1);
  if (threads > 1) threads = std::min(threads, static_cast<std::size_t>(1 + model::idle_cores()));
  model::parallel_for_chunks(
      cells.size(), kChunk, static_cast<int>(threads),
      [&](std::size_t begin, std::size_t end, int) {
        for (std::size_t i = begin; i < end; ++i) {
          const int cell = cells[i];
          grid->value[static_cast<std::size_t>(cell)] =
              likelihood.profile(grid->centre(cell % grid->columns, cell / grid->columns))
                  .log_density;
        }
      });
}

Grid evaluate_all(const CensoredLikelihood& likelihood, const SearchBox& box, double cell) {
  Grid grid;
  grid.origin = box.low;
  grid.cell = cell;
  grid.columns = std::max(1, static_cast<int>(std::ceil((box.high.x() - box.low.x()) / cell)));
  grid.rows = std::max(1, static_cast<int>(std::ceil((box.high.y() - box.low.y()) / cell)));
  grid.value.assign(static_cast<std::size_t>(grid.columns * grid.rows), kUnevaluated);
  std::vector<int> cells(grid.value.size());
  std::iota(cells.begin(), cells.end(), 0);
  evaluate_cells(likelihood, cells, &grid);
  return grid;
}

double best_of(const Grid& grid) {
  return *std::max_element(grid.value.begin(), grid.value.end());
}

// Whether (c, r) is at least as high as its evaluated neighbours.
bool local_maximum(const Grid& grid, int c, int r) {
  const double own = grid.at(c, r);
  if (own == kUnevaluated) return false;
  for (int dr = -1; dr <= 1; ++dr)
    for (int dc = -1; dc <= 1; ++dc) {
      const int cc = c + dc, rr = r + dr;
      if (cc < 0 || rr < 0 || cc >= grid.columns || rr >= grid.rows) continue;
      if (grid.at(cc, rr) > own) return false;
    }
  return true;
}

// The cells to refine: those within `keep` of the best, and the strongest local maxima (a
// sharp peak between coarse cell centres can leave its cell far below the best).
std::vector<char> cells_worth_refining(const Grid& coarse, double keep) {
  const double best = best_of(coarse);
  std::vector<char> chosen(coarse.value.size(), 0);
  std::vector<std::pair<double, int>> maxima;
  for (int r = 0; r < coarse.rows; ++r)
    for (int c = 0; c < coarse.columns; ++c) {
      const int i = r * coarse.columns + c;
      if (coarse.at(c, r) >= best - keep) chosen[static_cast<std::size_t>(i)] = 1;
      if (local_maximum(coarse, c, r)) maxima.emplace_back(coarse.at(c, r), i);
    }
  std::sort(maxima.begin(), maxima.end(), std::greater<>());
  for (std::size_t k = 0; k < maxima.size() && k < kRefinedMaxima; ++k)
    chosen[static_cast<std::size_t>(maxima[k].second)] = 1;
  return chosen;
}

// The chosen cells of `coarse` (and their neighbours), each split into `factor` x `factor`
// cells of the finer grid and evaluated there.
Grid refine(const Grid& coarse, const std::vector<char>& chosen, int factor,
            const CensoredLikelihood& likelihood) {
  std::vector<char> kept(coarse.value.size(), 0);
  int low_c = coarse.columns, low_r = coarse.rows, high_c = -1, high_r = -1;
  for (int r = 0; r < coarse.rows; ++r)
    for (int c = 0; c < coarse.columns; ++c) {
      if (!chosen[static_cast<std::size_t>(r * coarse.columns + c)]) continue;
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          const int cc = c + dc, rr = r + dr;
          if (cc < 0 || rr < 0 || cc >= coarse.columns || rr >= coarse.rows) continue;
          kept[static_cast<std::size_t>(rr * coarse.columns + cc)] = 1;
          low_c = std::min(low_c, cc);
          low_r = std::min(low_r, rr);
          high_c = std::max(high_c, cc);
          high_r = std::max(high_r, rr);
        }
    }
  Grid fine;
  fine.cell = coarse.cell / factor;
  fine.origin = coarse.origin + coarse.cell * model::Vec2(low_c, low_r);
  fine.columns = (high_c - low_c + 1) * factor;
  fine.rows = (high_r - low_r + 1) * factor;
  fine.value.assign(static_cast<std::size_t>(fine.columns * fine.rows), kUnevaluated);
  std::vector<int> cells;
  for (int r = low_r; r <= high_r; ++r)
    for (int c = low_c; c <= high_c; ++c) {
      if (!kept[static_cast<std::size_t>(r * coarse.columns + c)]) continue;
      for (int sr = 0; sr < factor; ++sr)
        for (int sc = 0; sc < factor; ++sc) {
          const int fc = (c - low_c) * factor + sc, fr = (r - low_r) * factor + sr;
          cells.push_back(fr * fine.columns + fc);
        }
    }
  evaluate_cells(likelihood, cells, &fine);
  return fine;
}

// Cells of the finer grid `chosen` leads to, with neighbours, at most. In floating point: over
// a wide box the factor reaches millions and factor * factor overflows an int (issue 53).
double cells_to_refine(const std::vector<char>& chosen, int factor) {
  const auto count = static_cast<double>(std::count(chosen.begin(), chosen.end(), 1));
  return count * 9.0 * static_cast<double>(factor) * static_cast<double>(factor);
}

// Each evaluated cell's basin: follow the steepest ascent among the 8 neighbours to a local
// maximum. Returns the maximum's index per cell (-1 for unevaluated cells).
std::vector<int> basins(const Grid& grid) {
  const int n = grid.columns * grid.rows;
  std::vector<int> up(static_cast<std::size_t>(n), -1);
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.columns; ++c) {
      const double own = grid.at(c, r);
      if (own == kUnevaluated) continue;
      int best = r * grid.columns + c;
      double best_value = own;
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          const int cc = c + dc, rr = r + dr;
          if (cc < 0 || rr < 0 || cc >= grid.columns || rr >= grid.rows) continue;
          if (grid.at(cc, rr) > best_value) {
            best_value = grid.at(cc, rr);
            best = rr * grid.columns + cc;
          }
        }
      up[static_cast<std::size_t>(r * grid.columns + c)] = best;
    }
  std::vector<int> root(static_cast<std::size_t>(n), -1);
  for (int i = 0; i < n; ++i) {
    if (up[static_cast<std::size_t>(i)] < 0) continue;
    int j = i;
    while (up[static_cast<std::size_t>(j)] != j) j = up[static_cast<std::size_t>(j)];
    root[static_cast<std::size_t>(i)] = j;
  }
  return root;
}

}  // namespace

PosteriorSearch search_posterior(const MergedScans& scans, const LikelihoodSettings& settings,
                                 const SearchBox& box, double credible_mass,
                                 double min_mode_separation, int levels) {
  const double extent = std::max(box.high.x() - box.low.x(), box.high.y() - box.low.y());
  const double first_cell = std::max(kLevels[0].cell, extent / kMaxCoarseCells);
  const auto cells_of = [&](const Level& level) -> const std::vector<ScanCell>& {
    return level.half_metre ? scans.half_metre : scans.metre;
  };
  Grid grid = evaluate_all(CensoredLikelihood(cells_of(kLevels[0]), settings), box, first_cell);
  bool half_metre = kLevels[0].half_metre;
  for (int level = 1; level < std::min(levels, 3); ++level) {
    const int factor = std::max(1, static_cast<int>(std::lround(grid.cell / kLevels[level].cell)));
    const auto max_cells = static_cast<double>(kLevels[level].max_cells);
    double keep = kLevels[level - 1].keep;
    std::vector<char> chosen = cells_worth_refining(grid, keep);
    // Out of the coarse grid, a very broad posterior keeps many cells: narrow the band until
    // the finer grid stays bounded (the strongest local maxima are refined whatever the band).
    while (level == 1 && keep > 1.0 && cells_to_refine(chosen, factor) > max_cells) {
      keep *= 0.5;
      chosen = cells_worth_refining(grid, keep);
    }
    if (cells_to_refine(chosen, factor) > max_cells) break;
    half_metre = kLevels[level].half_metre;
    grid = refine(grid, chosen, factor, CensoredLikelihood(cells_of(kLevels[level]), settings));
  }

  PosteriorSearch search;
  search.finest_half_metre = half_metre;
  const double best = best_of(grid);
  const double area = grid.cell * grid.cell;
  std::vector<double> weight(grid.value.size(), 0.0);
  double total = 0.0;
  for (std::size_t i = 0; i < grid.value.size(); ++i) {
    if (grid.value[i] == kUnevaluated) continue;
    weight[i] = std::exp(grid.value[i] - best) * area;
    total += weight[i];
  }

  // Modes: local maxima, strongest first, each absorbing weaker ones within the separation.
  const std::vector<int> root = basins(grid);
  std::vector<int> maxima;
  for (std::size_t i = 0; i < root.size(); ++i)
    if (root[i] == static_cast<int>(i)) maxima.push_back(static_cast<int>(i));
  std::sort(maxima.begin(), maxima.end(), [&](int a, int b) {
    return grid.value[static_cast<std::size_t>(a)] > grid.value[static_cast<std::size_t>(b)];
  });
  const auto centre_of = [&](int index) {
    return grid.centre(index % grid.columns, index / grid.columns);
  };
  std::vector<int> mode_of_maximum(grid.value.size(), -1);
  std::vector<int> mode_peaks;
  for (const int m : maxima) {
    int owner = -1;
    for (std::size_t k = 0; k < mode_peaks.size() && owner < 0; ++k)
      if ((centre_of(mode_peaks[k]) - centre_of(m)).norm() < min_mode_separation)
        owner = static_cast<int>(k);
    if (owner < 0) {
      owner = static_cast<int>(mode_peaks.size());
      mode_peaks.push_back(m);
    }
    mode_of_maximum[static_cast<std::size_t>(m)] = owner;
  }
  std::vector<PosteriorMode> modes(mode_peaks.size());
  std::vector<double> mass(mode_peaks.size(), 0.0);
  for (std::size_t i = 0; i < root.size(); ++i) {
    if (root[i] < 0) continue;
    const int m = mode_of_maximum[static_cast<std::size_t>(root[i])];
    mass[static_cast<std::size_t>(m)] += weight[i];
    modes[static_cast<std::size_t>(m)].mean += weight[i] * centre_of(static_cast<int>(i));
  }
  for (std::size_t k = 0; k < modes.size(); ++k) {
    modes[k].peak = centre_of(mode_peaks[k]);
    modes[k].peak_log_density = grid.value[static_cast<std::size_t>(mode_peaks[k])];
    modes[k].probability = mass[k] / total;
    if (mass[k] > 0) modes[k].mean /= mass[k];
  }
  for (std::size_t i = 0; i < root.size(); ++i) {
    if (root[i] < 0) continue;
    const auto m = static_cast<std::size_t>(mode_of_maximum[static_cast<std::size_t>(root[i])]);
    const model::Vec2 offset = centre_of(static_cast<int>(i)) - modes[m].mean;
    modes[m].covariance += weight[i] * offset * offset.transpose();
  }
  for (std::size_t k = 0; k < modes.size(); ++k) {
    // A cell's own spread (uniform over the cell) keeps a one-cell mode from claiming zero.
    if (mass[k] > 0) modes[k].covariance /= mass[k];
    modes[k].covariance += Eigen::Matrix2d::Identity() * area / 12.0;
  }
  std::sort(modes.begin(), modes.end(), [](const PosteriorMode& a, const PosteriorMode& b) {
    return a.probability > b.probability;
  });
  search.modes = std::move(modes);
  search.posterior = make_posterior(grid.origin, grid.cell, grid.columns, grid.rows,
                                    std::move(grid.value), credible_mass);
  return search;
}

}  // namespace rigdesign::localize::detail
