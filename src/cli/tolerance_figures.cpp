#include "tolerance_figures.hpp"

#include "rigdesign/io/file_bytes.hpp"
#include "rigdesign/metrics/tolerance_coverage.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/render/margin_plot.hpp"

namespace rigdesign::cli {

std::vector<report::ReportFigure> write_tolerance_figures(
    const model::Rig& rig, const model::SensorLibrary& library,
    const std::vector<model::SectorRequirement>& sectors, const metrics::CoverageSettings& settings,
    const std::string& folder, std::vector<std::string>* written) {
  std::vector<report::ReportFigure> figures;
  for (const metrics::ErrorSweep& sweep :
       metrics::tolerance_sweeps(rig, library, sectors, settings)) {
    const std::string axis = sweep.axis == 1 ? "pitch" : "yaw";
    render::MarginCurve curve;
    curve.axis_label = sweep.mount_id + " " + axis + " error [deg]";
    for (const double error : sweep.errors) curve.at.push_back(model::rad_to_deg(error));
    for (const double margin : sweep.smallest) curve.smallest.push_back(margin * 100);
    for (const auto& [name, margins] : sweep.sectors) {
      std::vector<double> points;
      for (const double margin : margins) points.push_back(margin * 100);
      curve.sectors.emplace_back(name, std::move(points));
    }
    const double width = model::rad_to_deg(sweep.half_width);
    curve.marks = {{-width, "-tolerance"}, {0.0, "nominal"}, {width, "+tolerance"}};
    const std::string title = "SC margin against " + sweep.mount_id + "'s " + axis +
                              " error (tolerance +-" + model::format_number(width, 3) + " deg)";
    const std::string stem = folder + "/tolerance_" + sweep.mount_id + "_" + axis;
    render::plot_margin_curve(curve, title, stem + ".png");
    render::plot_margin_curve(curve, title, stem + ".svg");
    if (written != nullptr) {
      written->push_back(stem + ".png");
      written->push_back(stem + ".svg");
    }
    figures.push_back({"tolerance-" + sweep.mount_id + "-" + axis,
                       title + ": the smallest margin over the requirement sectors (points of "
                               "SC) with the mount alone turned, the others nominal, exact path",
                       io::read_file_bytes(stem + ".svg", "an SVG picture")});
  }
  return figures;
}

}  // namespace rigdesign::cli
