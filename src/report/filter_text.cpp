#include "rigdesign/report/filter_text.hpp"

#include <ostream>

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/report/text_table.hpp"

namespace rigdesign::report {
namespace {

void print_cloud(const FilterCloudReport& cloud, const FilterCloudsReport& report,
                 std::ostream& out) {
  TextTable table;
  table.add_column("stage", TextTable::Align::left);
  for (const char* header : {"points in", "points out", "median ms", "p95 ms"})
    table.add_column(header, TextTable::Align::right);
  for (const filters::StageTiming& stage : cloud.stages) {
    table.add_row({stage.stage, std::to_string(stage.points_in), std::to_string(stage.points_out),
                   fixed(stage.seconds.median * 1e3, 2), fixed(stage.seconds.p95 * 1e3, 2)});
  }
  table.add_row({"total", std::to_string(cloud.points), std::to_string(cloud.points_out),
                 fixed(cloud.total.median * 1e3, 2), fixed(cloud.total.p95 * 1e3, 2)});
  out << cloud.file << ": " << cloud.points << " points (" << cloud.format << ", "
      << cloud.dropped_non_finite << " non-finite dropped), pipeline " << report.pipeline << ", "
      << report.runs << " runs\n";
  table.print(out, "  ");
  if (cloud.load) {
    out << "  filtering load of " << cloud.load->mount_id << " at " << cloud.load->frequency
        << " Hz: " << fixed(cloud.load->rate.cores, 3) << " core-equivalents of this machine ("
        << cloud.load->rate.seconds_per_point
        << " s per point: a catalog's filtering_seconds_per_point)\n";
  }
  if (!cloud.output.empty()) out << "  wrote " << cloud.output << '\n';
}

}  // namespace

void print_filter_clouds(const FilterCloudsReport& report, std::ostream& out) {
  for (const FilterCloudReport& cloud : report.clouds) print_cloud(cloud, report, out);
  out << "peak resident memory of the process: " << fixed(report.peak_memory_mib, 1) << " MiB\n";
}

void print_filter_scene(const FilterSceneReport& report, std::ostream& out) {
  TextTable table;
  table.add_column("mount", TextTable::Align::left);
  for (const char* header :
       {"points/frame", "out/frame", "median ms", "p95 ms", "F Hz", "U_f cores", "s per point"}) {
    table.add_column(header, TextTable::Align::right);
  }
  for (const FilterMountReport& mount : report.mounts) {
    table.add_row(
        {mount.mount_id, std::to_string(mount.points_per_frame),
         std::to_string(mount.kept_per_frame), fixed(mount.seconds_per_frame.median * 1e3, 2),
         fixed(mount.seconds_per_frame.p95 * 1e3, 2), fixed(mount.frequency, 0),
         fixed(mount.load.cores, 3), model::format_number(mount.load.seconds_per_point, 3)});
  }
  out << report.rig_name << " in the " << report.scene << " scene, pipeline " << report.pipeline
      << ", " << report.frames << " frames per sensor (single thread, this machine)\n";
  table.print(out, "  ");
  out << "  total filtering load U_f = " << fixed(report.total_load_cores, 3)
      << " core-equivalents of this machine; `s per point` is what a catalog's "
         "filtering_seconds_per_point takes\n";
  if (!report.loads_file.empty())
    out << "  wrote the loads per sensor to " << report.loads_file << '\n';
}

}  // namespace rigdesign::report
