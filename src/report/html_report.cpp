#include "rigdesign/report/html_report.hpp"

#include <sstream>

#include "rigdesign/io/emit/xml_text.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/report/requirement_text.hpp"
#include "rigdesign/report/text_table.hpp"

namespace rigdesign::report {
namespace {

void replace_all(std::string& text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos;
       at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
}

std::string mm(double metres) {
  return fixed(metres * 1000, 1);
}

std::string html_yes_no(bool value) {
  return value ? "yes" : "<b class=\"fail\">no</b>";
}

constexpr const char* kStyle = R"(
body { font-family: "DejaVu Sans", sans-serif; margin: 2em auto; max-width: 1250px; color: #222; }
h1 { font-size: 1.6em; } h2 { font-size: 1.25em; border-bottom: 1px solid #ccc; margin-top: 2em; }
table { border-collapse: collapse; margin: 0.5em 0; font-size: 0.9em; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: right; }
th { background: #f2f2f2; } td.text, th.text { text-align: left; }
.pass { color: #0a7a32; } .fail { color: #c01818; } .skip { color: #777; }
figure { margin: 1em 0; } figcaption { font-size: 0.9em; color: #555; }
svg { max-width: 100%; height: auto; } .meta { color: #555; font-size: 0.9em; }
)";

void verdict_table(std::ostringstream& html,
                   const std::vector<metrics::RequirementResult>& results) {
  html << "<section id=\"verdicts\"><h2>Requirements</h2>\n";
  if (results.empty()) {
    html << "<p>No requirements: the rig names none and none were given.</p></section>\n";
    return;
  }
  html << "<table><tr><th class=\"text\">requirement</th><th class=\"text\">verdict</th>"
          "<th class=\"text\">measured, required, margin</th><th class=\"text\">set by</th>"
          "<th class=\"text\">where (rig line, else requirement)</th><th class=\"text\">how it is "
          "judged</th></tr>\n";
  for (const metrics::RequirementResult& result : results) {
    const std::string verdict = to_string(result.verdict);
    const std::string css = result.verdict == metrics::Verdict::pass   ? "pass"
                            : result.verdict == metrics::Verdict::fail ? "fail"
                                                                       : "skip";
    html << "<tr><td class=\"text\">" << io::xml_escaped(result.id + " " + result.title)
         << "</td><td class=\"text " << css << "\">" << io::xml_escaped(verdict)
         << "</td><td class=\"text\">" << io::xml_escaped(measured_text(result))
         << "</td><td class=\"text\">" << io::xml_escaped(model::join(result.limiting_mounts))
         << "</td><td class=\"text\">"
         << io::xml_escaped(model::to_string(result.annotated_where()))
         << "</td><td class=\"text\">" << io::xml_escaped(result.explanation) << "</td></tr>\n";
  }
  html << "</table></section>\n";
}

void metrics_table(std::ostringstream& html, const metrics::ResultantMetrics& metrics) {
  html << "<section id=\"metrics\"><h2>Metrics per sensor and resultant (paper 1, section 2)</h2>\n"
          "<table><tr><th class=\"text\">mount</th><th class=\"text\">sensor / mode</th>"
          "<th>d [m]</th><th>F [Hz]</th><th>R [mm]</th><th>N [mm]</th><th>dark</th>"
          "<th>indoor</th><th>sun</th><th>B [MB/s]</th><th>U<sub>p</sub> [cores]</th>"
          "<th>price [USD]</th></tr>\n";
  for (const metrics::MountMetrics& mount : metrics.mounts) {
    html << "<tr><td class=\"text\">" << io::xml_escaped(mount.mount_id)
         << "</td><td class=\"text\">" << io::xml_escaped(mount.sensor_id + " / " + mount.mode_id)
         << "</td><td>" << fixed(mount.distance, 2) << "</td><td>" << fixed(mount.frequency, 1)
         << "</td><td>" << mm(mount.point_spacing) << "</td><td>" << mm(mount.noise) << "</td><td>"
         << html_yes_no(mount.light.dark) << "</td><td>" << html_yes_no(mount.light.indoor)
         << "</td><td>" << html_yes_no(mount.light.sunlight) << "</td><td>"
         << fixed(mount.bandwidth / 1e6, 2) << "</td><td>" << fixed(mount.driver_cpu, 2)
         << (mount.driver_cpu_basis == model::Basis::estimate ? "*" : "") << "</td><td>"
         << fixed(mount.price, 0) << (mount.price_basis == model::Basis::estimate ? "*" : "")
         << "</td></tr>\n";
  }
  html << "</table>\n<table><tr><th class=\"text\">resultant</th><th>value</th>"
          "<th class=\"text\">limiting sensors</th></tr>\n";
  const auto row = [&](const std::string& name, const std::string& value,
                       const std::vector<std::string>& mounts) {
    html << "<tr><td class=\"text\">" << name << "</td><td>" << io::xml_escaped(value)
         << "</td><td class=\"text\">" << io::xml_escaped(model::join(mounts)) << "</td></tr>\n";
  };
  row("F, slowest", fixed(metrics.frequency.value, 1) + " Hz", metrics.frequency.mounts);
  row("R, coarsest", mm(metrics.point_spacing.value) + " mm", metrics.point_spacing.mounts);
  row("N, noisiest", mm(metrics.noise.value) + " mm", metrics.noise.mounts);
  for (const metrics::LightResult& light : metrics.light) {
    row("L, " + model::to_string(light.condition), light.immune ? "every sensor works" : "fails",
        light.failing_mounts);
  }
  html << "</table><p class=\"meta\">* an estimate (sensors.yaml says why).</p></section>\n";
}

void cost_table(std::ostringstream& html, const metrics::ResultantMetrics& metrics) {
  html << "<section id=\"cost\"><h2>Cost model inputs (paper 1, eqs. 1-7)</h2>\n<table>"
          "<tr><th class=\"text\">item</th><th>value</th></tr>\n";
  for (const metrics::MountMetrics& mount : metrics.mounts) {
    html << "<tr><td class=\"text\">" << io::xml_escaped(mount.mount_id + ": " + mount.sensor_id)
         << "</td><td>" << fixed(mount.price, 0) << " USD"
         << (mount.price_basis == model::Basis::estimate ? " (estimate)" : "") << "</td></tr>\n";
  }
  html << "<tr><th class=\"text\">sensor cost C<sub>s</sub></th><th>"
       << fixed(metrics.sensor_cost, 0)
       << " USD</th></tr>\n<tr><td class=\"text\">bandwidth B</td><td>"
       << fixed(metrics.bandwidth / 1e6, 2) << " MB/s (" << fixed(metrics.bandwidth * 8 / 1e6, 1)
       << " Mbit/s)</td></tr>\n<tr><td class=\"text\">driver CPU load U<sub>p</sub></td><td>"
       << fixed(metrics.driver_cpu, 2)
       << " core-equivalents</td></tr>\n</table>\n<p class=\"meta\">Transfer hardware and CPU "
          "prices come from a catalog: <code>rigdesign select</code> adds them.</p></section>\n";
}

void n_minus_one_table(std::ostringstream& html, const metrics::RigCoverage& coverage) {
  html << "<section id=\"n-1\"><h2>N-1: spatial coverage with one sensor failed</h2>\n<table>"
          "<tr><th class=\"text\">without</th><th>SC complete min [%]</th><th>mean [%]</th>"
          "<th>SC floor min [%]</th><th>mean [%]</th></tr>\n";
  // Raster path on every row: the failed sensor's share, not the two paths' difference.
  html << "<tr><td class=\"text\">(all working)</td><td>"
       << fixed(coverage.complete_raster.min * 100, 1) << "</td><td>"
       << fixed(coverage.complete_raster.mean * 100, 1) << "</td><td>"
       << fixed(coverage.floor_raster.min * 100, 1) << "</td><td>"
       << fixed(coverage.floor_raster.mean * 100, 1) << "</td></tr>\n";
  for (const metrics::MountLoss& loss : coverage.without_each) {
    html << "<tr><td class=\"text\">" << io::xml_escaped(loss.mount_id) << "</td><td>"
         << fixed(loss.complete.min * 100, 1) << "</td><td>" << fixed(loss.complete.mean * 100, 1)
         << "</td><td>" << fixed(loss.floor.min * 100, 1) << "</td><td>"
         << fixed(loss.floor.mean * 100, 1) << "</td></tr>\n";
  }
  html << "</table></section>\n";
}

}  // namespace

std::string inline_svg(const std::string& svg, const std::string& prefix) {
  std::string text = svg;
  if (text.rfind("<?xml", 0) == 0) text.erase(0, text.find("?>") + 2);
  replace_all(text, "id=\"", "id=\"" + prefix);
  replace_all(text, "url(#", "url(#" + prefix);
  replace_all(text, "href=\"#", "href=\"#" + prefix);
  return text;
}

std::string html_report(const ReportContent& content) {
  const io::RigInputs& inputs = *content.inputs;
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>"
       << io::xml_escaped("rigdesign report: " + inputs.rig.name) << "</title>\n<style>" << kStyle
       << "</style>\n</head>\n<body>\n<h1>" << io::xml_escaped(inputs.rig.name)
       << "</h1>\n<p class=\"meta\">"
       << "rig " << io::xml_escaped(inputs.rig.file) << "; sensors from "
       << io::xml_escaped(inputs.library.file);
  if (inputs.requirements) html << "; requirements " << io::xml_escaped(inputs.requirements->file);
  html << "; body r = " << model::format_number(inputs.rig.body.radius)
       << " m, h = " << model::format_number(inputs.rig.body.height)
       << " m; distance of interest d = " << model::format_number(inputs.rig.distance_of_interest)
       << " m. Written by rigdesign "
       << "0.1.0.</p>\n";
  std::size_t failed = 0;
  for (const metrics::RequirementResult& result : content.results) {
    failed += result.verdict == metrics::Verdict::fail ? 1 : 0;
  }
  html << "<p id=\"summary\" class=\"" << (failed == 0 ? "pass" : "fail") << "\"><b>"
       << (content.results.empty() ? std::string("no requirements judged")
           : failed == 0           ? "every requirement met"
                                   : std::to_string(failed) + " requirement(s) fail")
       << "</b>; SC complete min " << fixed(content.coverage->complete.min * 100, 1) << " %, mean "
       << fixed(content.coverage->complete.mean * 100, 1) << " %.</p>\n";
  verdict_table(html, content.results);
  for (const ReportSection& section : content.sections) {
    html << "<section id=\"" << section.id << "\"><h2>" << io::xml_escaped(section.title)
         << "</h2>\n"
         << section.html << "</section>\n";
  }
  metrics_table(html, *content.metrics);
  html << "<section id=\"figures\"><h2>Coverage pictures</h2>\n";
  for (std::size_t i = 0; i < content.figures.size(); ++i) {
    const ReportFigure& figure = content.figures[i];
    html << "<figure id=\"" << figure.id << "\">\n"
         << inline_svg(figure.svg, "f" + std::to_string(i) + "-") << "\n<figcaption>"
         << io::xml_escaped(figure.caption) << "</figcaption></figure>\n";
  }
  html << "</section>\n";
  n_minus_one_table(html, *content.coverage);
  cost_table(html, *content.metrics);
  html << "</body>\n</html>\n";
  return html.str();
}

}  // namespace rigdesign::report
