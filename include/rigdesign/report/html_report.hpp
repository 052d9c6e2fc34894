#pragma once
// `rigdesign report`'s page: one self-contained HTML file (inline SVG and CSS, no script, no
// network) with a rig's verdicts, metrics, coverage pictures, N-1 table and costs.
#include <string>
#include <vector>

#include "rigdesign/io/config/rig_inputs.hpp"
#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/metrics/requirement_check.hpp"
#include "rigdesign/metrics/resultant.hpp"

namespace rigdesign::report {

/// A picture for the page: its caption and the SVG document's text.
struct ReportFigure {
  std::string id;  ///< HTML id, e.g. "sc-cartesian"
  std::string caption;
  std::string svg;
};

/// A section of its own, e.g. a selection's trace: HTML the caller built (escaped already).
struct ReportSection {
  std::string id;
  std::string title;
  std::string html;
};

struct ReportContent {
  const io::RigInputs* inputs = nullptr;
  const metrics::ResultantMetrics* metrics = nullptr;
  const metrics::RigCoverage* coverage = nullptr;
  std::vector<metrics::RequirementResult> results;
  std::vector<ReportFigure> figures;
  std::vector<ReportSection> sections;  ///< after the verdicts
};

std::string html_report(const ReportContent& content);

/// `svg` made fit to sit inline beside other SVGs: the XML prolog dropped and every id
/// (and reference to one) prefixed with `prefix`, so clip paths of two pictures cannot clash.
std::string inline_svg(const std::string& svg, const std::string& prefix);

}  // namespace rigdesign::report
