// Issue 54 item 2: every quantitative statement paper 3 makes about its sweeps, on its tables
// and on ours.
#include "rigdesign/occupancy/paper3_statements.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "rigdesign/model/format_number.hpp"

namespace rigdesign::occupancy {
namespace {

constexpr double kSweepUndefined = std::numeric_limits<double>::quiet_NaN();

const Scores kNoScores{kSweepUndefined, kSweepUndefined, kSweepUndefined, kSweepUndefined,
                       kSweepUndefined};

struct SweepColumn {
  std::vector<double> x;
  std::vector<Scores> paper;
  std::vector<Scores> ours;
  bool complete = true;  // every row has a run
};

SweepColumn column_of(const Paper3Sweep& sweep, const RunLookup& runs) {
  SweepColumn column;
  for (const Paper3Setting& row : sweep.rows) {
    column.x.push_back(row.value);
    column.paper.push_back(row.paper);
    const OccupancyRun* run = runs(paper3_mapper_name(row));
    column.complete = column.complete && run != nullptr;
    column.ours.push_back(run ? run->all.object : kNoScores);
  }
  return column;
}

std::string three(double v) {
  return std::isnan(v) ? "-" : model::format_number(v, 3);
}

// The values of one score down a sweep, "P .347, .519, ...".
std::string listed(const char* name, const std::vector<Scores>& scores, double Scores::*field) {
  std::string text = std::string(name);
  for (std::size_t i = 0; i < scores.size(); ++i)
    text += (i == 0 ? " " : ", ") + three(scores[i].*field);
  return text;
}

bool non_decreasing(const std::vector<Scores>& scores, double Scores::*field) {
  for (std::size_t i = 1; i < scores.size(); ++i) {
    if (!(scores[i].*field >= scores[i - 1].*field - 0.01)) return false;
  }
  return !scores.empty();
}

// Scores this close to the best tie with it: three decimals, as the paper prints them.
constexpr double kTie = 5e-4;

// The settings at the best score: one, or all that tie with it (none without scores).
std::vector<double> best_x(const std::vector<double>& x, const std::vector<Scores>& scores,
                           double Scores::*field) {
  double best = -std::numeric_limits<double>::infinity();
  for (const Scores& s : scores) best = std::max(best, s.*field);
  std::vector<double> at_best;
  for (std::size_t i = 0; i < scores.size(); ++i)
    if (scores[i].*field >= best - kTie) at_best.push_back(x[i]);
  return at_best;
}

// A single best setting, or NaN when the best is tied or missing: a tie names no peak.
double argmax_x(const std::vector<double>& x, const std::vector<Scores>& scores,
                double Scores::*field) {
  const std::vector<double> at_best = best_x(x, scores, field);
  return at_best.size() == 1 ? at_best.front() : kSweepUndefined;
}

std::string best_text(const std::vector<double>& at_best) {
  std::string text = at_best.size() == 1 ? "best at " : "tied best at ";
  for (std::size_t i = 0; i < at_best.size(); ++i) text += (i ? ", " : "") + three(at_best[i]);
  return text;
}

double at_x(const std::vector<double>& x, const std::vector<Scores>& scores, double value,
            double Scores::*field) {
  for (std::size_t i = 0; i < x.size(); ++i)
    if (std::abs(x[i] - value) < 1e-9) return scores[i].*field;
  return kSweepUndefined;
}

const Paper3Sweep* find_sweep(std::span<const Paper3Sweep> sweeps, const std::string& name) {
  for (const Paper3Sweep& sweep : sweeps)
    if (sweep.name == name) return &sweep;
  return nullptr;
}

bool near(double a, double b) {
  return std::abs(a - b) < 1e-9;
}

// Statements are added only when every row they read has a run.
class Statements {
 public:
  Statements(std::span<const Paper3Sweep> sweeps, const RunLookup& runs)
      : sweeps_(sweeps), runs_(runs) {}

  // The column of a sweep with a run for every row, or nullopt.
  std::optional<SweepColumn> column(const std::string& name) const {
    const Paper3Sweep* sweep = find_sweep(sweeps_, name);
    if (!sweep) return std::nullopt;
    SweepColumn c = column_of(*sweep, runs_);
    if (!c.complete) return std::nullopt;
    return c;
  }

  // A statement decided by `holds` on the paper's scores and on ours, with `shown` listed.
  template <class Holds>
  void add(const std::string& statement, const std::string& sweeps, const SweepColumn& c,
           Holds holds, const char* shown, double Scores::*field, bool from_text = true) {
    trends_.push_back({statement, sweeps, holds(c.paper), holds(c.ours),
                       listed(shown, c.paper, field), listed(shown, c.ours, field), from_text});
  }

  void add_decided(Paper3Trend trend) { trends_.push_back(std::move(trend)); }
  const RunLookup& runs() const { return runs_; }
  std::vector<Paper3Trend> take() { return std::move(trends_); }

 private:
  std::span<const Paper3Sweep> sweeps_;
  const RunLookup& runs_;
  std::vector<Paper3Trend> trends_;
};

bool in_range(double x, double low, double high) {
  return x >= low - 1e-9 && x <= high + 1e-9;
}

// Per resolution sweep: precision rising, where recall peaks, where F1 peaks.
void resolution_statements(Statements& out) {
  for (const std::string name : {"octomap:resolution", "skimap:resolution", "voxblox:resolution"}) {
    const std::optional<SweepColumn> c = out.column(name);
    if (!c) continue;
    out.add(
        "precision rises with voxel length", name, *c,
        [](const std::vector<Scores>& s) { return non_decreasing(s, &Scores::precision); }, "P",
        &Scores::precision);
    const auto recall_peak_in = [&](double low, double high) {
      return [&, low, high](const std::vector<Scores>& s) {
        return in_range(argmax_x(c->x, s, &Scores::recall), low, high);
      };
    };
    if (name == "octomap:resolution")
      out.add("recall peaks near 0.1 m (0.075-0.125 m)", name, *c, recall_peak_in(0.075, 0.125),
              "R", &Scores::recall);
    if (name == "skimap:resolution")
      out.add("recall peaks at 0.075-0.1 m", name, *c, recall_peak_in(0.075, 0.1), "R",
              &Scores::recall);
    if (name == "voxblox:resolution") {
      out.add(
          "recall drops below 0.15 m voxels (each under half the recall at 0.15 m)", name, *c,
          [&](const std::vector<Scores>& s) {
            const double at_015 = at_x(c->x, s, 0.15, &Scores::recall);
            for (std::size_t i = 0; i < c->x.size(); ++i)
              if (c->x[i] < 0.15 - 1e-9 && !(s[i].recall < 0.5 * at_015)) return false;
            return !std::isnan(at_015);
          },
          "R", &Scores::recall);
    }
    out.add(
        "F1 peaks near 0.15 m (0.125-0.175 m)", name, *c,
        [&](const std::vector<Scores>& s) {
          return in_range(argmax_x(c->x, s, &Scores::f1), 0.125, 0.175);
        },
        "F1", &Scores::f1);
  }
}

// OctoMap's probabilities and SkiMap's minimum weight.
void probability_statements(Statements& out) {
  if (const std::optional<SweepColumn> c = out.column("octomap:hit")) {
    out.add(
        "hit probability 1 gives OctoMap's best F1", "octomap:hit", *c,
        [&](const std::vector<Scores>& s) { return near(argmax_x(c->x, s, &Scores::f1), 1.0); },
        "F1 (0.5, 0.7, 1)", &Scores::f1);
    out.add(
        "precision about constant for hit probabilities 0.7 and 1 (within 0.03)", "octomap:hit", *c,
        [&](const std::vector<Scores>& s) {
          return std::abs(at_x(c->x, s, 0.7, &Scores::precision) -
                          at_x(c->x, s, 1.0, &Scores::precision)) <= 0.03;
        },
        "P (0.5, 0.7, 1)", &Scores::precision);
  }
  if (const std::optional<SweepColumn> c = out.column("octomap:miss")) {
    out.add(
        "a low miss probability: miss 0.7 collapses (F1 under half of 0.2's and 0.4's)",
        "octomap:miss", *c,
        [&](const std::vector<Scores>& s) {
          return at_x(c->x, s, 0.7, &Scores::f1) <
                 0.5 * std::min(at_x(c->x, s, 0.2, &Scores::f1), at_x(c->x, s, 0.4, &Scores::f1));
        },
        "F1 (0.2, 0.4, 0.7)", &Scores::f1);
  }
  if (const std::optional<SweepColumn> c = out.column("skimap:min_weight")) {
    out.add(
        "a minimum weight of 1 gives SkiMap's best F1", "skimap:min_weight", *c,
        [&](const std::vector<Scores>& s) { return near(argmax_x(c->x, s, &Scores::f1), 1.0); },
        "F1 (1, 5, 10)", &Scores::f1);
  }
}

// Voxblox's truncation and weights.
void voxblox_statements(Statements& out) {
  if (const std::optional<SweepColumn> c = out.column("voxblox:truncation")) {
    out.add(
        "voxel/truncation ratio 2 (truncation 0.05 m) beats 1 and Voxblox's recommended 0.5 in "
        "recall",
        "voxblox:truncation", *c,
        [&](const std::vector<Scores>& s) {
          const double r2 = at_x(c->x, s, 0.05, &Scores::recall);
          return r2 > at_x(c->x, s, 0.1, &Scores::recall) &&
                 r2 > at_x(c->x, s, 0.2, &Scores::recall);
        },
        "R (0.05, 0.1, 0.2)", &Scores::recall);
  }
  if (const std::optional<SweepColumn> c = out.column("voxblox:const_weight")) {
    out.add(
        "constant weight lowers Voxblox's recall", "voxblox:const_weight", *c,
        [&](const std::vector<Scores>& s) {
          return at_x(c->x, s, 1.0, &Scores::recall) < at_x(c->x, s, 0.0, &Scores::recall);
        },
        "R (true, false)", &Scores::recall);
  }
}

// A mapper's reference row as the sweeps hold it: paper 3's scores and our run.
struct ReferenceRow {
  Scores paper;
  const OccupancyRun* run = nullptr;
};

std::optional<ReferenceRow> reference_row(std::span<const Paper3Sweep> sweeps, Paper3Mapper mapper,
                                          const RunLookup& runs) {
  for (const Paper3Sweep& sweep : sweeps) {
    if (sweep.rows.empty() || sweep.rows.front().mapper != mapper) continue;
    Paper3Common common;
    common.voxblox_rule = sweep.rows.front().voxblox.occupied_rule;
    const std::string name = paper3_mapper_name(paper3_reference(mapper, common));
    const OccupancyRun* run = runs(name);
    if (!run) continue;
    for (const Paper3Setting& row : sweep.rows)
      if (paper3_mapper_name(row) == name) return ReferenceRow{row.paper, run};
  }
  return std::nullopt;
}

std::string precision_recall(const Scores& s) {
  return "P " + three(s.precision) + ", R " + three(s.recall);
}

// What the text says across mappers, on each mapper's reference row.
void reference_statements(std::span<const Paper3Sweep> sweeps, Statements& out) {
  const std::pair<Paper3Mapper, const char*> mappers[] = {{Paper3Mapper::octomap, "OctoMap"},
                                                          {Paper3Mapper::skimap, "SkiMap"},
                                                          {Paper3Mapper::voxblox, "Voxblox"}};
  std::vector<std::optional<ReferenceRow>> rows;
  for (const auto& [mapper, name] : mappers) {
    rows.push_back(reference_row(sweeps, mapper, out.runs()));
    const std::optional<ReferenceRow>& row = rows.back();
    if (!row) continue;
    const Scores& ours = row->run->all.object;
    out.add_decided({std::string("recall below precision (paper 3: occlusion hides part of the "
                                 "actor), ") +
                         name + "'s reference row",
                     row->run->mapper, row->paper.recall < row->paper.precision,
                     ours.recall < ours.precision, precision_recall(row->paper),
                     precision_recall(ours)});
  }
  if (rows[0] && rows[1] && rows[2]) {
    const auto skimap_best = [&](double (*f1)(const ReferenceRow&)) {
      return f1(*rows[1]) > f1(*rows[0]) && f1(*rows[1]) > f1(*rows[2]);
    };
    const auto paper_f1 = [](const ReferenceRow& r) { return r.paper.f1; };
    const auto our_f1 = [](const ReferenceRow& r) { return r.run->all.object.f1; };
    const auto listed_f1 = [&](double (*f1)(const ReferenceRow&)) {
      return "F1 OctoMap " + three(f1(*rows[0])) + ", SkiMap " + three(f1(*rows[1])) +
             ", Voxblox " + three(f1(*rows[2]));
    };
    out.add_decided(
        {"SkiMap scores the best F1 of the three at the reference rows (\"marginally "
         "best by numbers\")",
         "reference rows", skimap_best(paper_f1), skimap_best(our_f1), listed_f1(paper_f1),
         listed_f1(our_f1)});
  }
  if (rows[0] && rows[1]) {
    const OccupancyRun& ski = *rows[1]->run;
    const OccupancyRun& octo = *rows[0]->run;
    out.add_decided(
        {"SkiMap keeps the voxels the actor passed through occupied (more of the "
         "person's trail shown than OctoMap's, reference rows)",
         ski.mapper + ", " + octo.mapper, true, ski.all.trail_area > octo.all.trail_area,
         "stated in the text, no number",
         "mean trail area " + model::format_number(ski.all.trail_area, 3) + " m2 vs OctoMap " +
             model::format_number(octo.all.trail_area, 3) + " m2; ghost area " +
             model::format_number(ski.all.ghost_area, 3) + " vs " +
             model::format_number(octo.all.ghost_area, 3) + " m2"});
  }
}

// What each table shows without a sentence: its best setting by P, by R and by F1.
void table_statements(std::span<const Paper3Sweep> sweeps, Statements& out) {
  const std::pair<const char*, double Scores::*> scores[] = {
      {"P", &Scores::precision}, {"R", &Scores::recall}, {"F1", &Scores::f1}};
  for (const Paper3Sweep& sweep : sweeps) {
    const std::optional<SweepColumn> c = out.column(sweep.name);
    if (!c) continue;
    for (const auto& [label, field] : scores) {
      const double paper_best = argmax_x(c->x, c->paper, field);
      const std::vector<double> our_best = best_x(c->x, c->ours, field);
      out.add_decided(
          {sweep.table + ": the best " + label + " at " + sweep.swept + " " + three(paper_best),
           sweep.name, !std::isnan(paper_best),
           our_best.size() == 1 && near(paper_best, our_best.front()),
           listed(label, c->paper, field),
           best_text(our_best) + "; " + listed(label, c->ours, field), false});
    }
  }
}

}  // namespace

std::vector<Paper3Trend> paper3_trends(std::span<const Paper3Sweep> sweeps, const RunLookup& runs) {
  Statements out(sweeps, runs);
  resolution_statements(out);
  probability_statements(out);
  voxblox_statements(out);
  reference_statements(sweeps, out);
  table_statements(sweeps, out);
  return out.take();
}

}  // namespace rigdesign::occupancy
