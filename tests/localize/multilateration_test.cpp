#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "localize/censored_likelihood.hpp"
#include "rigdesign/localize/chunking.hpp"
#include "rigdesign/localize/emitter_localizer.hpp"
#include "rigdesign/localize/geometry_analysis.hpp"
#include "rigdesign/localize/range_fit.hpp"
#include "rigdesign/localize/scan_series.hpp"
#include "rigdesign/localize/wls_multilateration.hpp"

using namespace rigdesign;

namespace {

// Noise-free log: RSSI from the path-loss model at the exact distance to `emitter`.
localize::RssiLog exact_log(const std::vector<model::Vec3>& positions, const model::Vec3& emitter,
                            const localize::PathLossParams& model) {
  localize::RssiLog log;
  log.emitters = {"e"};
  double t = 0;
  for (const model::Vec3& p : positions)
    log.readings.push_back({t++, p, 0, localize::rssi_at_range((emitter - p).norm(), model)});
  return log;
}

// An L-shaped ground path with readings every 0.3 m, each at the centre of its 10 cm chunk
// ((m + 0.5) 0.1 m in x, y and z), so the chunk centres are the reading positions and
// noise-free ranges are solved exactly.
constexpr double kAntennaHeight = 0.45;  // [m], a cell centre
std::vector<model::Vec3> l_path() {
  std::vector<model::Vec3> positions;
  for (int k = 0; k <= 33; ++k) positions.emplace_back(-9.95 + 0.3 * k, 0.05, kAntennaHeight);
  for (int k = 1; k <= 33; ++k) positions.emplace_back(0.05, 0.05 + 0.3 * k, kAntennaHeight);
  return positions;
}

// A chunk of `count` readings at cell centre `centre`, each `range` from the emitter.
localize::Chunk make_chunk(const model::Vec3& centre, double range, int count) {
  localize::Chunk chunk;
  chunk.centre = centre;
  chunk.height_sum = count * centre.z();
  chunk.range_sum = count * range;
  chunk.count = count;
  return chunk;
}

}  // namespace

TEST_CASE("path loss: range and RSSI are inverse, the paper's model at hand-computed points",
          "[localize]") {
  localize::PathLossParams model;  // a = -45 dBm, n = 2.5
  CHECK(localize::rssi_at_range(1.0, model) == Approx(-45.0));
  CHECK(localize::rssi_at_range(10.0, model) == Approx(-70.0));  // -45 - 25 log10(10)
  CHECK(localize::range_from_rssi(-70.0, model) == Approx(10.0));
  CHECK(localize::range_from_rssi(-57.5, model) == Approx(std::sqrt(10.0)));  // 10^(12.5 / 25)
}

TEST_CASE("chunks stand at their cells' centres, average the distances, drop -80 dBm or worse",
          "[localize]") {
  localize::PathLossParams
      model;  // -45 dBm -> 1 m, -70 dBm -> 10 m, -95 dBm -> 100 m (below the cut-off)
  // The thesis drops "-80 dBm or worse": -80 itself is not used, -79.9 is.
  CHECK_FALSE(localize::passes_cutoff(-80.0, model));
  CHECK_FALSE(localize::passes_cutoff(-95.0, model));
  CHECK(localize::passes_cutoff(-79.9, model));
  localize::RssiLog log;
  log.emitters = {"a", "b"};
  log.readings = {{0, {0.01, 0.02, 0.4}, 0, -45.0},  {1, {0.05, 0.06, 0.4}, 0, -70.0},
                  {2, {0.15, 0.02, 0.4}, 0, -70.0},  {3, {0.16, 0.03, 0.4}, 0, -95.0},
                  {4, {-0.05, 0.02, 0.4}, 0, -70.0}, {5, {0.02, 0.02, 0.4}, 1, -40.0},
                  {6, {0.03, 0.03, 0.4}, 0, -80.0}};
  const std::vector<localize::Chunk> chunks = localize::chunk_readings(log, 0, model);
  REQUIRE(chunks.size() == 3);  // cells [0, 0.1), [0.1, 0.2) and [-0.1, 0) in x
  CHECK(chunks[0].count == 2);  // the -80 dBm reading was dropped
  // The chunk is the cell [0, 0.1) x [0, 0.1): its centre, not the readings' mean (0.03, 0.04).
  CHECK(chunks[0].position().x() == Approx(0.05));
  CHECK(chunks[0].position().y() == Approx(0.05));
  CHECK(chunks[0].mean_height() == Approx(0.4));  // the antenna's height, for a 2D solve's z
  // Paper 4 averages distances: (1 + 10) / 2 = 5.5 m, not the 3.16 m of the mean RSSI.
  CHECK(chunks[0].mean_range() == Approx(5.5));
  CHECK(chunks[0].mean_rssi() == Approx(-57.5));
  CHECK(localize::wls_weight(chunks[0]) == Approx(std::sqrt(2.0) / 5.5));
  CHECK(chunks[1].count == 1);  // the -95 dBm reading was dropped
  CHECK(chunks[1].position().x() == Approx(0.15));
  CHECK(localize::wls_weight(chunks[1]) == Approx(0.1));
  CHECK(chunks[2].position().x() == Approx(-0.05));
}

TEST_CASE("eq. 12 as printed and as weighted least squares, worked by hand on four chunks",
          "[localize]") {
  // p1 (0, 0) r 1 (reference: k1 = 0 - 1 = -1); p2 (2, 0) r 2 c 4: w 1, a = (4 - 4) + 1 = 1;
  // p3 (0, 2) r 1 c 1: w 1, a = (4 - 1) + 1 = 4; p4 (2, 2) r 2 c 1: w 0.5, a = (8 - 4) + 1 = 5.
  // Rows 2 (p_j - p1): B = [4 0; 0 4; 4 4].
  const std::vector<localize::Chunk> chunks = {
      make_chunk({0, 0, 0}, 1.0, 1), make_chunk({2, 0, 0}, 2.0, 4), make_chunk({0, 2, 0}, 1.0, 1),
      make_chunk({2, 2, 0}, 2.0, 1)};
  // Literal (paper): least squares of B q = diag(w) a = (1, 4, 2.5): B^T B = [32 16; 16 32],
  // B^T (w a) = (14, 26), q = [32 -16; -16 32] (14, 26) / 768 = (32, 608) / 768 = (1/24, 19/24).
  const auto paper = localize::wls_multilateration(chunks, 2, localize::WlsReference::first_chunk,
                                                   localize::WlsWeighting::paper);
  REQUIRE(paper);
  CHECK(paper->position.x() == Approx(1.0 / 24.0));
  CHECK(paper->position.y() == Approx(19.0 / 24.0));
  // Weighted least squares (rows): w^2 = (1, 1, 0.25): H = [20 4; 4 20], g = (9, 21),
  // q = [20 -4; -4 20] (9, 21) / 384 = (96, 384) / 384 = (0.25, 1).
  const auto rows = localize::wls_multilateration(chunks, 2, localize::WlsReference::first_chunk,
                                                  localize::WlsWeighting::rows);
  REQUIRE(rows);
  CHECK(rows->position.x() == Approx(0.25));
  CHECK(rows->position.y() == Approx(1.0));
}

TEST_CASE(
    "paper 4's weight w = sqrt(c) / r scales each equation; the old variant weighted its square",
    "[localize]") {
  // Five chunks whose ranges disagree (no common point), so the weighting moves the answer.
  struct Row {
    double x, y, range;
    int count;
  };
  const std::vector<Row> rows = {
      {0, 0, 5.0, 1}, {6, 0, 4.0, 3}, {6, 6, 6.5, 2}, {0, 6, 3.0, 4}, {3, -2, 7.0, 1}};
  std::vector<localize::Chunk> chunks;
  for (const Row& r : rows) chunks.push_back(make_chunk({r.x, r.y, 0.0}, r.range, r.count));
  // The linearised system written out row by row (chunk j minus the first chunk):
  // 2 (p_j - p_1)^T q = (|p_j|^2 - r_j^2) - (|p_1|^2 - r_1^2), and its weighted normal equations.
  const auto explicit_solution = [&](bool square_the_weight) {
    Eigen::Matrix2d normal = Eigen::Matrix2d::Zero();
    Eigen::Vector2d right = Eigen::Vector2d::Zero();
    const Eigen::Vector2d p1(rows[0].x, rows[0].y);
    const double k1 = p1.squaredNorm() - rows[0].range * rows[0].range;
    for (std::size_t j = 1; j < rows.size(); ++j) {
      const Eigen::Vector2d p(rows[j].x, rows[j].y);
      const Eigen::Vector2d a = 2.0 * (p - p1);
      const double b = p.squaredNorm() - rows[j].range * rows[j].range - k1;
      const double w = std::sqrt(static_cast<double>(rows[j].count)) / rows[j].range;
      const double weight = square_the_weight ? w * w : w;
      normal += weight * a * a.transpose();
      right += weight * a * b;
    }
    return Eigen::Vector2d(normal.ldlt().solve(right));
  };
  const auto rows_weighted = localize::wls_multilateration(
      chunks, 2, localize::WlsReference::first_chunk, localize::WlsWeighting::rows);
  const auto squares_weighted = localize::wls_multilateration(
      chunks, 2, localize::WlsReference::first_chunk, localize::WlsWeighting::squared_residuals);
  REQUIRE(rows_weighted);
  REQUIRE(squares_weighted);
  const Eigen::Vector2d expected_rows = explicit_solution(true);
  const Eigen::Vector2d expected_squares = explicit_solution(false);
  CHECK((rows_weighted->position.head<2>() - expected_rows).norm() < 1e-9);
  CHECK((squares_weighted->position.head<2>() - expected_squares).norm() < 1e-9);
  CHECK((expected_rows - expected_squares).norm() > 0.05);  // the two really differ here
  // Eq. 12 as printed, diag(w) a = B q, solved with B's pseudo-inverse written out here.
  Eigen::MatrixXd B(rows.size() - 1, 2);
  Eigen::VectorXd weighted_a(rows.size() - 1);
  const Eigen::Vector2d p1(rows[0].x, rows[0].y);
  const double k1 = p1.squaredNorm() - rows[0].range * rows[0].range;
  for (std::size_t j = 1; j < rows.size(); ++j) {
    const Eigen::Vector2d p(rows[j].x, rows[j].y);
    const auto i = static_cast<Eigen::Index>(j - 1);
    B.row(i) = 2.0 * (p - p1).transpose();
    const double w = std::sqrt(static_cast<double>(rows[j].count)) / rows[j].range;
    weighted_a(i) = w * (p.squaredNorm() - rows[j].range * rows[j].range - k1);
  }
  const Eigen::Vector2d expected_paper =
      B.completeOrthogonalDecomposition().pseudoInverse() * weighted_a;
  const auto literal = localize::wls_multilateration(chunks, 2, localize::WlsReference::first_chunk,
                                                     localize::WlsWeighting::paper);
  REQUIRE(literal);
  CHECK((literal->position.head<2>() - expected_paper).norm() < 1e-9);
  // The default is the paper's.
  const auto by_default = localize::wls_multilateration(chunks, 2);
  REQUIRE(by_default);
  CHECK((by_default->position.head<2>() - expected_rows).norm() < 1e-9);
}

TEST_CASE("the incremental system equals the batch system after every reading, every weighting",
          "[localize]") {
  const model::Vec3 emitter(-3.0, 4.0, kAntennaHeight);
  localize::PathLossParams model;
  const localize::RssiLog log = exact_log(l_path(), emitter, model);
  for (const localize::WlsWeighting weighting :
       {localize::WlsWeighting::rows, localize::WlsWeighting::paper,
        localize::WlsWeighting::squared_residuals}) {
    localize::ChunkParams chunking;
    chunking.weighting = weighting;
    localize::IncrementalWls incremental(model, chunking);
    localize::ChunkAccumulator batch(chunking);
    for (const localize::RssiReading& r : log.readings) {
      incremental.add(r.position, r.rssi_dbm);
      batch.add(r.position, localize::range_from_rssi(r.rssi_dbm, model), r.rssi_dbm);
      const auto a = incremental.solve(2);
      const auto b = localize::wls_multilateration(batch.chunks(), 2,
                                                   localize::WlsReference::first_chunk, weighting);
      REQUIRE(a.has_value() == b.has_value());
      if (a) CHECK((a->position - b->position).norm() < 1e-6);
    }
  }
}

TEST_CASE("noise-free ranges are recovered exactly in 2D by every linear variant and the range fit",
          "[localize]") {
  // At the antenna's height: the 2D problem is exact.
  const model::Vec3 emitter(-3.0, 4.0, kAntennaHeight);
  localize::PathLossParams model;
  const localize::RssiLog log = exact_log(l_path(), emitter, model);
  const std::vector<localize::Chunk> chunks = localize::chunk_readings(log, 0, model);
  const localize::GeometryAnalysis geometry = localize::analyse_geometry(chunks);
  REQUIRE(geometry.dimensions == 2);
  REQUIRE_FALSE(geometry.collinear);
  for (const localize::WlsReference reference :
       {localize::WlsReference::first_chunk, localize::WlsReference::weighted_mean}) {
    const auto solution = localize::wls_multilateration(chunks, 2, reference);
    REQUIRE(solution);
    CHECK((solution->position - emitter).norm() < 1e-6);
  }
  // Eq. 12 as printed weights only the right-hand side, so exact ranges give another point
  // (the equations hold at the emitter, B q = a, not their rescaled right-hand sides).
  const auto literal = localize::wls_multilateration(chunks, 2, localize::WlsReference::first_chunk,
                                                     localize::WlsWeighting::paper);
  REQUIRE(literal);
  CHECK((literal->position - emitter).norm() > 0.1);
  // The range fit models a vertical offset between antenna and emitter; these readings have
  // none, so the fit is told so, and the assumed level is 5 dB off: the fit finds -45 dBm.
  localize::RangeFitParams fit;
  fit.vertical_offset = 0.0;
  fit.level_prior_db = 100;          // the level is free
  fit.path_prior_scale = 0;          // no prior on the position
  fit.correlated_shadowing = false;  // noise-free: nothing to temper
  model.rssi_at_1m_dbm = -40.0;      // assumed 5 dB off
  const localize::RangeFitResult result =
      localize::fit_ranges(localize::scan_series(log, 0), model, fit);
  REQUIRE_FALSE(result.hypotheses.empty());
  // Scans are merged into 0.25 m cells at their mean position: exact to a few centimetres.
  CHECK((result.hypotheses[0].position.head<2>() - emitter.head<2>()).norm() < 0.05);
  CHECK(result.hypotheses[0].probability > 0.99);
  CHECK(result.hypotheses[0].rssi_at_1m_dbm == Approx(-45.0).margin(0.25));
}

TEST_CASE("noise-free ranges are recovered exactly in 3D from a path that climbs (wls)",
          "[localize]") {
  const model::Vec3 emitter(2.0, -1.0, 1.5);
  localize::PathLossParams model;
  std::vector<model::Vec3> helix;
  for (int i = 0; i < 400; ++i) {
    const double angle = 0.05 * i;
    // 0 to 4 m up; each reading at its chunk's centre ((m + 0.5) 0.1 m) so the ranges are exact.
    const model::Vec3 p(6 * std::cos(angle), 6 * std::sin(angle), 0.01 * i);
    helix.push_back(((p / 0.1).array().floor() + 0.5).matrix() * 0.1);
  }
  const std::vector<localize::Chunk> chunks =
      localize::chunk_readings(exact_log(helix, emitter, model), 0, model);
  const localize::GeometryAnalysis geometry = localize::analyse_geometry(chunks);
  REQUIRE(geometry.dimensions == 3);
  const auto linear = localize::wls_multilateration(chunks, 3);
  REQUIRE(linear);
  CHECK((linear->position - emitter).norm() < 1e-6);
}

TEST_CASE("collinear positions are reported as degenerate, with both mirror images", "[localize]") {
  const model::Vec3 emitter(2.0, 3.0, 0.4);
  localize::PathLossParams model;
  std::vector<model::Vec3> line;
  for (double x = -15; x <= 15; x += 0.2) line.emplace_back(x, 0.0, 0.4);
  const localize::RssiLog log = exact_log(line, emitter, model);
  const localize::EmitterEstimate wls =
      localize::localize_emitter(log, 0, localize::LocalizeMethod::wls);
  CHECK(wls.geometry.collinear);
  CHECK(wls.hypotheses.empty());  // the linear system is singular: no confident point
  localize::LocalizeParams params;
  params.fit.vertical_offset = 0.0;  // the readings have none
  params.fit.correlated_shadowing = false;
  const localize::EmitterEstimate nls =
      localize::localize_emitter(log, 0, localize::LocalizeMethod::nls, params);
  CHECK(nls.geometry.collinear);
  REQUIRE(nls.hypotheses.size() == 2);
  // The two mirror images explain the data exactly alike: equal probabilities, and the result
  // says so instead of ranking them.
  CHECK(nls.ambiguous);
  CHECK(nls.hypotheses[0].probability == Approx(0.5).margin(0.01));
  CHECK(nls.hypotheses[1].probability == Approx(0.5).margin(0.01));
  const model::Vec2 mirror(2.0, -3.0);
  const model::Vec2 a = nls.hypotheses[0].position.head<2>();
  const model::Vec2 b = nls.hypotheses[1].position.head<2>();
  // Each peak is refined until the simplex is 1 cm across (kPeakTolerance): within ~1.5 cm each.
  CHECK(std::min((a - emitter.head<2>()).norm() + (b - mirror).norm(),
                 (a - mirror).norm() + (b - emitter.head<2>()).norm()) < 3e-2);
  CHECK(nls.hypotheses[0].side == -nls.hypotheses[1].side);
  // --prefer-side puts the left one (y > 0 for a robot driving along +x) first, then right.
  for (const int side : {1, -1}) {
    params.prefer_side = side;
    const localize::EmitterEstimate preferred =
        localize::localize_emitter(log, 0, localize::LocalizeMethod::nls, params);
    REQUIRE(preferred.hypotheses.size() == 2);
    CHECK(preferred.hypotheses[0].side == side);
    CHECK(preferred.hypotheses[0].position.y() * side > 2.9);
    CHECK(preferred.tie_break == (side > 0 ? "--prefer-side left" : "--prefer-side right"));
  }
  // A wall map breaks the tie with evidence: an 8 dB wall along y = -1.5 for x < 0 would dim
  // the mirror image for the scans west of it but not east: the readings show no such step.
  params.prefer_side = 0;
  params.walls = {{{-30, -1.5}, {0, -1.5}, 8.0}};
  const localize::EmitterEstimate walled =
      localize::localize_emitter(log, 0, localize::LocalizeMethod::nls, params);
  REQUIRE_FALSE(walled.hypotheses.empty());
  CHECK_FALSE(walled.ambiguous);
  CHECK((walled.hypotheses[0].position.head<2>() - emitter.head<2>()).norm() < 2e-2);
}

TEST_CASE("geometry: height spread decides 2D or 3D, the mirror reflects across the path",
          "[localize]") {
  std::vector<localize::Chunk> chunks(2);
  chunks[0] = make_chunk({0, 0, 0.4}, 1.0, 1);
  chunks[1] = make_chunk({10, 0, 0.4}, 1.0, 1);
  const localize::GeometryAnalysis g = localize::analyse_geometry(chunks);
  CHECK(g.dimensions == 2);
  CHECK(g.collinear);
  CHECK(g.along_spread == Approx(5.0));  // two points 10 m apart: standard deviation 5 m
  const model::Vec3 image = g.mirror({3, 2, 0.4});
  CHECK((image - model::Vec3(3, -2, 0.4)).norm() < 1e-12);
}

TEST_CASE("a circular path with unknown level reports the inverse-point twin", "[localize]") {
  // Every point X of the circle |X| = 12 sees (4, 0) and its inverse (144 / 4, 0) = (36, 0) at
  // the distance ratio 12 / 4 = 3: the twin's level is 25 log10(3) = 11.93 dB stronger.
  // 2 dB of white noise (seeded): noise-free data would make both peaks far narrower than the
  // search grid's cells.
  const model::Vec3 emitter(4.0, 0.0, 0.4);
  localize::PathLossParams model;
  std::vector<model::Vec3> circle;
  for (int i = 0; i < 750; ++i) {
    const double angle = 2 * 3.14159265358979 * i / 750;
    circle.emplace_back(12 * std::cos(angle), 12 * std::sin(angle), 0.4);
  }
  localize::RssiLog log = exact_log(circle, emitter, model);
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 2.0);
  for (localize::RssiReading& r : log.readings) r.rssi_dbm += noise(random);
  const std::vector<localize::Chunk> chunks = localize::chunk_readings(log, 0, model);
  const localize::GeometryAnalysis geometry = localize::analyse_geometry(chunks);
  REQUIRE(geometry.circular);
  // Chunks stand at cell centres, each within half a 10 cm cell's diagonal (0.071 m) of the
  // circle, so the fitted radius is within that of 12 m.
  CHECK(geometry.circle_radius == Approx(12.0).margin(0.071));
  localize::RangeFitParams fit;
  fit.vertical_offset = 0.0;
  fit.level_prior_db = 100;  // the level is free
  fit.exponent_prior = 0;    // the exponent is known
  fit.path_prior_scale = 0;
  fit.correlated_shadowing = false;
  fit.search_margin = 30;  // the twin lies 24 m beyond the path
  const localize::RangeFitResult result =
      localize::fit_ranges(localize::scan_series(log, 0), model, fit);
  REQUIRE(result.hypotheses.size() >= 2);
  CHECK(result.ambiguous);
  const model::Vec2 twin(36.0, 0.0);
  for (std::size_t i = 0; i < 2; ++i) {
    const localize::Hypothesis& h = result.hypotheses[i];
    const bool is_phone = (h.position.head<2>() - emitter.head<2>()).norm() < 0.2;
    CHECK((is_phone || (h.position.head<2>() - twin).norm() < 1.0));
    CHECK(h.rssi_at_1m_dbm == Approx(is_phone ? -45.0 : -45.0 + 25 * std::log10(3.0)).margin(0.5));
  }
}

TEST_CASE("scan series: missed scans are placed on straight gaps, left out across bends",
          "[localize]") {
  // One scan a second at 1 m/s: along +x to (10, 0), then along +y. Not heard at t = 4, 5, 6
  // (a straight gap: chord 4 m in 4 s) and at t = 9, 10, 11 (around the corner: (8, 0) to
  // (10, 2) is a chord of 2.83 m for 4 m driven).
  localize::RssiLog log;
  log.emitters = {"a"};
  for (int t = 0; t <= 16; ++t) {
    if ((t >= 4 && t <= 6) || (t >= 9 && t <= 11)) continue;
    const model::Vec3 p = t <= 10 ? model::Vec3(t, 0, 0.4) : model::Vec3(10, t - 10, 0.4);
    log.readings.push_back({static_cast<double>(t), p, 0, -60.0 - t});
  }
  log.readings.push_back({17.0, {10, 7, 0.4}, 0, 0.0, false});  // logged: scanned, not heard
  const localize::ScanSeries series = localize::scan_series(log, 0);
  CHECK(series.scan_period_s == 1.0);
  CHECK(series.heard == 11);
  CHECK(series.unheard_interpolated == 3);
  CHECK(series.unheard_unplaced == 3);
  CHECK(series.unheard_logged == 1);
  // No floor given: the weakest reading, -76 dBm at t = 16.
  CHECK(series.floor_source == localize::FloorSource::weakest_reading);
  CHECK(series.floor_dbm == -76.0);
  REQUIRE(series.scans.size() == 15);
  CHECK_FALSE(series.scans[4].heard);
  CHECK((series.scans[5].position - model::Vec3(5, 0, 0.4)).norm() < 1e-12);
  // A floor from the log wins over the weakest reading, an option over both.
  log.floor_dbm = -95.0;
  CHECK(localize::scan_series(log, 0).floor_source == localize::FloorSource::log);
  localize::ScanSeriesParams params;
  params.floor_dbm = -90.0;
  CHECK(localize::scan_series(log, 0, params).floor_dbm == -90.0);
}

TEST_CASE("censored likelihood: log Phi and the inverse Mills ratio at hand-checked points",
          "[localize]") {
  // Phi(-1) = 0.158655253931457, Phi(0) = 1/2, phi(0) = 1/sqrt(2 pi).
  CHECK(localize::detail::log_normal_cdf(-1.0) == Approx(std::log(0.158655253931457)));
  CHECK(localize::detail::inverse_mills_ratio(0.0) ==
        Approx(2.0 / std::sqrt(2 * 3.14159265358979)));
  // The tail expansions join erfc at z = -30 without a step (relative 1e-9).
  CHECK(localize::detail::log_normal_cdf(-30.0 - 1e-9) ==
        Approx(localize::detail::log_normal_cdf(-30.0 + 1e-9)).epsilon(1e-9));
  CHECK(localize::detail::inverse_mills_ratio(-30.0 - 1e-9) ==
        Approx(localize::detail::inverse_mills_ratio(-30.0 + 1e-9)).epsilon(1e-9));
}

TEST_CASE("censored likelihood: the tabulated tail agrees with erfc everywhere it is used",
          "[localize]") {
  // Off the table's knots (a step of 1/32 and an irrational offset), across its whole span.
  double worst_log_cdf = 0.0, worst_mills = 0.0;
  for (double z = -29.99; z < 9.5; z += 0.0123456789) {
    const localize::detail::NormalTail table = localize::detail::normal_tail(z);
    const localize::detail::NormalTail exact = localize::detail::exact_normal_tail(z);
    worst_log_cdf = std::max(worst_log_cdf, std::abs(table.log_cdf - exact.log_cdf));
    // Relative where lambda is large (the lower tail, lambda ~ -z), absolute where it vanishes.
    worst_mills = std::max(worst_mills, std::abs(table.inverse_mills - exact.inverse_mills) /
                                            std::max(exact.inverse_mills, 1.0));
  }
  CHECK(worst_log_cdf < 1e-8);
  CHECK(worst_mills < 1e-8);
  CHECK(localize::detail::log_normal_cdf(-1.0) == Approx(std::log(0.158655253931457)));
}

TEST_CASE("unheard scans push the estimate away from where the emitter was not heard",
          "[localize]") {
  // A 60 m straight road; the phone 4 m beside x = 0 and a floor of -75 dBm: beyond about
  // 10^(30 / 25) = 15.8 m the scans hear nothing. Those scans are known (empty-rssi lines), and
  // with them the posterior puts no mass near the unheard stretches.
  const model::Vec3 emitter(0.0, 4.0, 0.4);
  localize::PathLossParams model;
  localize::RssiLog log;
  log.emitters = {"a"};
  log.floor_dbm = -75.0;
  for (int i = 0; i <= 600; ++i) {
    const model::Vec3 p(-30.0 + 0.1 * i, 0.0, 0.4);
    const double rssi = localize::rssi_at_range((emitter - p).norm(), model);
    log.readings.push_back({0.1 * i, p, 0, rssi, rssi >= -75.0});
  }
  localize::LocalizeParams params;
  params.fit.vertical_offset = 0.0;
  params.fit.correlated_shadowing = false;
  const localize::EmitterEstimate estimate =
      localize::localize_emitter(log, 0, localize::LocalizeMethod::nls, params);
  REQUIRE(estimate.scans);
  CHECK(estimate.scans->unheard_logged > 200);
  REQUIRE_FALSE(estimate.hypotheses.empty());
  for (const localize::Hypothesis& h : estimate.hypotheses) CHECK(std::abs(h.position.x()) < 0.1);
  CHECK_FALSE(estimate.region->contains({-20.0, 4.0}));
  CHECK_FALSE(estimate.region->contains({20.0, -4.0}));
}
