#include "coverage_files.hpp"

#include <nlohmann/json.hpp>
#include <sstream>

#include "rigdesign/geometry/body_mesh.hpp"
#include "rigdesign/geometry/body_occluder.hpp"
#include "rigdesign/geometry/housing_geometry.hpp"
#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/io/file_bytes.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/render/coverage_plots.hpp"
#include "rigdesign/render/fov_mesh.hpp"
#include "rigdesign/render/palette.hpp"
#include "rigdesign/render/view_3d_figure.hpp"
#include "rigdesign/report/json_report.hpp"

namespace rigdesign::cli {

std::string coverage_csv(const metrics::RigCoverage& coverage) {
  std::ostringstream csv;
  csv << "theta_deg,r_m,sc_complete,sc_floor,sc_complete_raster,sc_floor_raster,redundancy,"
         "coarsest_mount,coarsest_spacing_m,noisiest_mount,noisiest_noise_m,seen_by\n";
  for (const metrics::AngleCoverage& angle : coverage.angles) {
    csv << model::format_number(model::rad_to_deg(angle.theta), 8) << ','
        << model::format_number(angle.r, 8) << ',' << model::format_number(angle.complete, 8) << ','
        << model::format_number(angle.floor, 8) << ','
        << model::format_number(angle.complete_raster, 8) << ','
        << model::format_number(angle.floor_raster, 8) << ','
        << model::format_number(angle.redundancy, 8) << ',';
    if (angle.coarsest_mount >= 0) {
      csv << coverage.mount_ids[angle.coarsest_mount] << ','
          << model::format_number(angle.coarsest_spacing, 8) << ','
          << coverage.mount_ids[angle.noisiest_mount] << ','
          << model::format_number(angle.noisiest_noise, 8) << ',';
    } else {
      csv << ",,,,";
    }
    std::string seen;
    for (std::size_t i = 0; i < angle.mount_sees.size(); ++i) {
      if (angle.mount_sees[i]) seen += (seen.empty() ? "" : ";") + coverage.mount_ids[i];
    }
    csv << seen << '\n';
  }
  return csv.str();
}

std::vector<std::pair<render::Viewpoint, std::string>> views_3d() {
  return {{render::Viewpoint::isometric, "view_isometric"}, {render::Viewpoint::top, "view_top"}};
}

std::vector<std::string> write_coverage_files(const model::Rig& rig,
                                              const model::SensorLibrary& library,
                                              const metrics::RigCoverage& coverage,
                                              const std::vector<double>& angles_deg,
                                              const std::string& folder, bool with_3d) {
  std::vector<std::string> written;
  const auto path = [&](const std::string& name) {
    written.push_back(folder + "/" + name);
    return written.back();
  };
  for (const char* extension : {".png", ".svg"}) {
    render::plot_sc_cartesian(coverage, rig.name, path(std::string("sc_cartesian") + extension));
    render::plot_sc_polar(coverage, rig.name, path(std::string("sc_polar") + extension));
  }
  for (const double degrees : angles_deg) {
    const metrics::SectionView view =
        metrics::section_view(rig, library, model::deg_to_rad(degrees));
    const std::string name = "section_" + model::format_number(degrees, 6);
    render::draw_section(view, rig.name, path(name + ".png"));
    render::draw_section(view, rig.name, path(name + ".svg"));
  }
  if (with_3d) {
    for (const auto& [viewpoint, name] : views_3d()) {
      render_rig_3d(rig, library, viewpoint, path(name + ".png"));
      render_rig_3d(rig, library, viewpoint, path(name + ".svg"));
    }
  }
  io::write_file_atomically(path("coverage.csv"), coverage_csv(coverage));
  io::write_file_atomically(path("coverage.json"), report::to_json(coverage, true).dump(2) + "\n");
  return written;
}

void render_rig_3d(const model::Rig& rig, const model::SensorLibrary& library,
                   render::Viewpoint viewpoint, const std::string& path) {
  std::vector<render::ColouredMesh> meshes;
  meshes.push_back({geometry::body_mesh(rig.body), render::kBodyColour, 1.0});
  for (model::BodyPart& support : geometry::support_parts(rig))
    meshes.push_back({std::move(support.triangles), render::kBodyColour, 1.0});
  render::View3dOverlay overlay;
  overlay.title = rig.name + ": what each sensor sees, to d = " +
                  model::format_number(rig.distance_of_interest) + " m (" +
                  (viewpoint == render::Viewpoint::top ? "top view" : "isometric view") + ")";
  overlay.subtitle =
      "each volume is cut where the body blocks the sensor's rays, as the coverage numbers count "
      "it";
  // The same occluder the coverage engine uses, so the picture agrees with the numbers.
  const geometry::BodyOccluder body(rig.body);
  for (std::size_t i = 0; i < rig.mounts.size(); ++i) {
    const model::Mount& mount = rig.mounts[i];
    const model::SensorMode& mode = *library.find(mount.sensor_id)->find_mode(mount.mode_id);
    meshes.push_back(
        {render::visible_fov_mesh(mode, mount.T_robot_sensor, rig.distance_of_interest, body),
         render::sensor_colour(i), 0.35});
    if (auto housing = geometry::mount_housing(mount, library))
      meshes.push_back({std::move(housing->triangles), render::sensor_colour(i), 1.0});
    overlay.legend.push_back(
        {render::sensor_colour(i), mount.id + ": " + mount.sensor_id + " / " + mount.mode_id});
    overlay.labels.push_back(
        {mount.T_robot_sensor.translation(), mount.id, render::sensor_colour(i)});
  }
  render::View3dSettings settings;
  settings.viewpoint = viewpoint;
  settings.extent = 0.0;  // fit the FOV volumes, which reach past d from off-centre mounts
  render::render_view_3d(meshes, settings, overlay, path);
}

std::vector<report::ReportFigure> coverage_figures(const std::string& folder,
                                                   const std::vector<double>& angles_deg) {
  std::vector<report::ReportFigure> figures;
  const auto add = [&](const std::string& id, const std::string& file, const std::string& caption) {
    figures.push_back({id, caption, io::read_file_bytes(folder + "/" + file, "an SVG picture")});
  };
  add("sc-cartesian", "sc_cartesian.svg",
      "Spatial Coverage at every azimuth: SC complete and floor, requirement sectors shaded, "
      "and per sensor the angles where it sees the cross-section.");
  add("sc-polar", "sc_polar.svg", "The same seen from above, forward up.");
  for (const double degrees : angles_deg) {
    const std::string name = model::format_number(degrees);
    add("section-" + name, "section_" + name + ".svg",
        "Cross-section at theta = " + name +
            " deg: each sensor's region, the body, the floor seen.");
  }
  add("view-isometric", "view_isometric.svg",
      "What each sensor sees to d, cut where the body blocks it (isometric).");
  add("view-top", "view_top.svg", "The same from above.");
  return figures;
}

}  // namespace rigdesign::cli
