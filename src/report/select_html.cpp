#include "rigdesign/report/select_html.hpp"

#include <sstream>

#include "rigdesign/io/emit/xml_text.hpp"
#include "rigdesign/report/html_report.hpp"
#include "rigdesign/report/text_table.hpp"

namespace rigdesign::report {
namespace {

// What each relaxation step asked and what the cheapest rig then cost.
void trace_table(const SelectReport& report, std::ostringstream& html) {
  const model::RelaxationPolicy& policy = *report.policy;
  html << "<p>Catalog " << io::xml_escaped(report.catalog->file) << ", budget "
       << usd(report.budget) << ", policy "
       << io::xml_escaped(policy.file.empty() ? std::string("none") : policy.file)
       << ".</p>\n<table><tr><th>#</th><th class=\"text\">relaxed</th><th class=\"text\">"
          "needs</th><th>cost [USD]</th><th class=\"text\">within budget</th><th>nodes</th>"
          "<th>seconds</th></tr>\n";
  const std::vector<select::RelaxationIteration>& iterations = report.outcome->iterations;
  for (std::size_t i = 0; i < iterations.size(); ++i) {
    const select::RelaxationIteration& it = iterations[i];
    html << "<tr><td>" << i << "</td><td class=\"text\">"
         << io::xml_escaped(it.relaxed.empty() ? "-" : it.relaxed) << "</td><td class=\"text\">"
         << io::xml_escaped(describe(it.targets)) << "</td><td>"
         << (it.selection.found ? fixed(it.selection.cost.total, 0) : "none") << "</td><td class=\""
         << (it.within_budget ? "text pass\">yes" : "text fail\">no") << "</td><td>"
         << it.selection.search.nodes << "</td><td>" << fixed(it.selection.seconds, 2)
         << "</td></tr>\n";
  }
  html << "</table>\n";
}

void chosen_cost_table(const select::CostBreakdown& cost, std::ostringstream& html) {
  html << "<table><tr><th class=\"text\">chosen rig's cost</th><th>USD</th></tr>\n"
       << "<tr><td class=\"text\">sensors</td><td>" << fixed(cost.sensors, 0) << "</td></tr>\n"
       << "<tr><td class=\"text\">transfer: " << io::xml_escaped(cost.transfer_id) << "</td><td>"
       << fixed(cost.transfer, 0)
       << "</td></tr>\n<tr><td class=\"text\">CPU: " << io::xml_escaped(cost.cpu_id) << "</td><td>"
       << fixed(cost.cpu, 0) << "</td></tr>\n<tr><th class=\"text\">total</th><th>"
       << fixed(cost.total, 0) << "</th></tr>\n</table>\n";
}

}  // namespace

std::string selection_trace_html(const SelectReport& report,
                                 const select::RelaxationIteration& pick,
                                 const std::string& pareto_svg) {
  std::ostringstream html;
  trace_table(report, html);
  chosen_cost_table(pick.selection.cost, html);
  html << "<p>" << io::xml_escaped(describe(pick.selection, *report.catalog)) << "</p>\n";
  html << "<figure id=\"pareto\">" << inline_svg(pareto_svg, "pareto-")
       << "<figcaption>Cost against mean coverage of the rigs meeting the requirements of the "
          "chosen step.</figcaption></figure>\n";
  return html.str();
}

}  // namespace rigdesign::report
