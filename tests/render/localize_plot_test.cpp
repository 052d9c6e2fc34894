// A localisation plot frames where the robot went: an estimate far outside is shown as an
// arrow on the frame's edge and listed with its coordinates, not allowed to set the axes.
#include "rigdesign/render/localize_plot.hpp"

#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "support/temp_folder.hpp"

using namespace rigdesign;

namespace {

std::string plot_svg_text(const std::string& path) {
  std::ifstream file(path);
  std::stringstream bytes;
  bytes << file.rdbuf();
  return bytes.str();
}

// Every <text> element's words.
std::vector<std::string> svg_texts(const std::string& svg) {
  std::vector<std::string> texts;
  for (std::size_t open = svg.find("<text"); open != std::string::npos;
       open = svg.find("<text", open + 1)) {
    const std::size_t start = svg.find('>', open) + 1;
    texts.push_back(svg.substr(start, svg.find("</text>", start) - start));
  }
  return texts;
}

}  // namespace

TEST_CASE("a localize plot keeps its axes on the path and lists what lies beyond") {
  render::LocalizePlot plot;
  plot.title = "square walk";
  for (int i = 0; i <= 40; ++i) {  // a 10 m x 10 m square
    const double s = i / 4.0;
    plot.path.emplace_back(std::min(s, 10.0), 0.0, 0.0);
    plot.path.emplace_back(10.0, std::min(s, 10.0), 0.0);
  }
  plot.markers.push_back(
      {model::Vec3(5, 5, 0), Eigen::Matrix2d::Zero(), "truth", render::PlotMarkerKind::truth});
  plot.markers.push_back({model::Vec3(150, -3, 0), Eigen::Matrix2d::Identity(), "wild",
                          render::PlotMarkerKind::estimate});
  const test::TempFolder folder;
  const std::string path = folder.path() + "/plot.svg";
  render::plot_localization(plot, path);
  const std::vector<std::string> texts = svg_texts(plot_svg_text(path));
  bool noted = false, listed = false;
  double largest_tick = -1e300;
  for (const std::string& text : texts) {
    noted = noted || text.find("1 marker(s) beyond the region shown") != std::string::npos;
    listed = listed || text.find("wild at (150, -3) m") != std::string::npos;
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (!text.empty() && end == text.c_str() + text.size())
      largest_tick = std::max(largest_tick, value);
  }
  CHECK(noted);
  CHECK(listed);
  // The path spans 0..10 m; with the 5 m margin the axes end near 15 m, far from 150.
  CHECK(largest_tick < 30);
  CHECK(largest_tick >= 10);
}
