#pragma once
// What the two SC charts (Cartesian and polar) share: their title, the requirement sectors as
// degree ranges, where each mount sees the section, and their legend entries. Private to
// render/.
#include <cairo.h>

#include <string>
#include <utility>
#include <vector>

#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/render/palette.hpp"

namespace rigdesign::render {

inline constexpr Rgb kRedundancyColour{0.45, 0.45, 0.45};
inline constexpr Rgb kPassColour{0.0, 0.55, 0.25};  ///< a requirement sector met
inline constexpr Rgb kFailColour{0.8, 0.1, 0.1};    ///< a requirement sector missed

std::string coverage_title(const metrics::RigCoverage& coverage, const std::string& rig_name);

/// A sector as one or two [from, to] degree ranges inside [0, 360].
std::vector<std::pair<double, double>> sector_ranges_deg(const model::SectorRequirement& sector);

/// The runs of consecutive sampled angles where mount `mount` sees part of the section, as
/// [from, to] degree spans (each sample stands for the half steps either side of it).
std::vector<std::pair<double, double>> mount_spans(const metrics::RigCoverage& coverage,
                                                   std::size_t mount);

/// "id (sensor)", or the id alone when the sensor is not known.
std::string mount_label(const metrics::RigCoverage& coverage, std::size_t mount);

/// A legend entry: a 30 px line (dashed or not) and its label, baseline at y.
void legend_line(cairo_t* cairo, double x, double y, const Rgb& colour, bool dashed,
                 const std::string& label);

/// A legend entry: a 30 px box and its label, baseline at y.
void legend_box(cairo_t* cairo, double x, double y, const Rgb& colour, const std::string& label,
                double size = 13);

}  // namespace rigdesign::render
