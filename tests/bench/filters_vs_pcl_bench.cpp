// Our filter stages and pipelines against PCL 1.13's on the same clouds, in the same
// process, single thread: per-stage medians, PCL / ours ratios and output point counts side
// by side. Built only when libpcl-dev is present (scripts/install-pcl.sh). Run through
// scripts/bench.sh filters.
#include <pcl/ModelCoefficients.h>
#include <pcl/filters/extract_indices.h>
#include <pcl/filters/passthrough.h>
#include <pcl/filters/radius_outlier_removal.h>
#include <pcl/filters/statistical_outlier_removal.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/point_types.h>
#include <pcl/segmentation/sac_segmentation.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "front_camera_cloud.hpp"
#include "openmp_regions.hpp"
#include "rigdesign/filters/pipeline.hpp"
#include "rigdesign/filters/radius_outlier.hpp"
#include "rigdesign/io/cloud/cloud_io.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/sim/rig_simulation.hpp"
#include "rigdesign/sim/scene_library.hpp"

namespace {

using namespace rigdesign;
using PclCloud = pcl::PointCloud<pcl::PointXYZ>;

constexpr int kRuns = 15;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

PclCloud::Ptr to_pcl(const model::PointCloud& cloud) {
  PclCloud::Ptr out(new PclCloud);
  out->reserve(cloud.size());
  for (const model::Point3f& p : cloud.points) out->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  return out;
}

// PCL's versions of paper 1's stages with the same parameters.
PclCloud::Ptr pcl_voxel(const PclCloud::Ptr& in, float leaf) {
  PclCloud::Ptr out(new PclCloud);
  pcl::VoxelGrid<pcl::PointXYZ> filter;
  filter.setInputCloud(in);
  filter.setLeafSize(leaf, leaf, leaf);
  filter.filter(*out);
  return out;
}

PclCloud::Ptr pcl_sor(const PclCloud::Ptr& in) {
  PclCloud::Ptr out(new PclCloud);
  pcl::StatisticalOutlierRemoval<pcl::PointXYZ> filter;
  filter.setInputCloud(in);
  filter.setMeanK(10);
  filter.setStddevMulThresh(1.0);
  filter.filter(*out);
  return out;
}

PclCloud::Ptr pcl_pass(const PclCloud::Ptr& in, bool negative) {
  PclCloud::Ptr out(new PclCloud);
  pcl::PassThrough<pcl::PointXYZ> filter;
  filter.setInputCloud(in);
  filter.setFilterFieldName("z");
  filter.setFilterLimits(-0.10f, 0.10f);
  filter.setNegative(negative);
  filter.filter(*out);
  return out;
}

pcl::PointIndices::Ptr pcl_plane(const PclCloud::Ptr& in, pcl::ModelCoefficients& coefficients) {
  pcl::PointIndices::Ptr inliers(new pcl::PointIndices);
  pcl::SACSegmentation<pcl::PointXYZ> segmentation;
  segmentation.setOptimizeCoefficients(true);
  segmentation.setModelType(pcl::SACMODEL_PLANE);
  segmentation.setMethodType(pcl::SAC_RANSAC);
  segmentation.setMaxIterations(100);
  segmentation.setDistanceThreshold(0.03);
  segmentation.setInputCloud(in);
  if (!in->empty()) segmentation.segment(*inliers, coefficients);
  return inliers;
}

// Floor removal 1 in PCL: slice, RANSAC on the slice, remove the slice's inliers.
PclCloud::Ptr pcl_floor_1(const PclCloud::Ptr& in) {
  pcl::PointIndices::Ptr slice(new pcl::PointIndices);
  for (std::size_t i = 0; i < in->size(); ++i) {
    if ((*in)[i].z >= -0.10f && (*in)[i].z <= 0.10f) slice->indices.push_back(static_cast<int>(i));
  }
  PclCloud::Ptr slice_cloud(new PclCloud(*in, slice->indices));
  pcl::ModelCoefficients coefficients;
  const pcl::PointIndices::Ptr plane = pcl_plane(slice_cloud, coefficients);
  pcl::PointIndices::Ptr removed(new pcl::PointIndices);
  for (const int i : plane->indices)
    removed->indices.push_back(slice->indices[static_cast<std::size_t>(i)]);
  PclCloud::Ptr out(new PclCloud);
  pcl::ExtractIndices<pcl::PointXYZ> extract;
  extract.setInputCloud(in);
  extract.setIndices(removed);
  extract.setNegative(true);
  extract.filter(*out);
  return out;
}

// Floor removal 2 in PCL, as ours (paper 1): the slice, a 30 cm voxel copy of it on which a
// plane within 15 degrees of horizontal is found, then the slice's points within 3 cm of it
// removed.
PclCloud::Ptr pcl_floor_2(const PclCloud::Ptr& in) {
  const PclCloud::Ptr coarse = pcl_voxel(pcl_pass(in, false), 0.30f);
  pcl::ModelCoefficients c;
  pcl::PointIndices inliers;
  pcl::SACSegmentation<pcl::PointXYZ> segmentation;
  segmentation.setOptimizeCoefficients(true);
  segmentation.setModelType(pcl::SACMODEL_PERPENDICULAR_PLANE);
  segmentation.setAxis(Eigen::Vector3f::UnitZ());
  segmentation.setEpsAngle(15.0 * M_PI / 180.0);
  segmentation.setMethodType(pcl::SAC_RANSAC);
  segmentation.setMaxIterations(100);
  segmentation.setDistanceThreshold(0.03);
  segmentation.setInputCloud(coarse);
  if (!coarse->empty()) segmentation.segment(inliers, c);
  PclCloud::Ptr out(new PclCloud);
  if (c.values.size() != 4) return in;
  for (const auto& p : *in) {
    const bool in_slice = p.z >= -0.10f && p.z <= 0.10f;
    if (!in_slice ||
        std::abs(c.values[0] * p.x + c.values[1] * p.y + c.values[2] * p.z + c.values[3]) > 0.03f)
      out->push_back(p);
  }
  return out;
}

// Paper 2's outlier removal in PCL with our defaults (radius 5 cm, 2 neighbours).
PclCloud::Ptr pcl_radius_outlier(const PclCloud::Ptr& in) {
  const model::RadiusOutlierParams params;
  PclCloud::Ptr out(new PclCloud);
  pcl::RadiusOutlierRemoval<pcl::PointXYZ> filter;
  filter.setInputCloud(in);
  filter.setRadiusSearch(params.radius);
  filter.setMinNeighborsInRadius(params.min_neighbours);
  filter.filter(*out);
  return out;
}

/// One stage or pipeline: ours, PCL as shipped, and PCL with its OpenMP regions run inline on
/// the calling thread (the fair peer: same algorithm, one thread, no per-query team start).
struct Row {
  std::string name;
  double ours = 0, shipped = 0, serial = 0;  // medians [s]
  std::size_t ours_points = 0, pcl_points = 0;
  double regions_per_call = 0;  // PCL's OpenMP regions per call
};

/// Times `ours` and `pcl` in interleaved rounds (ours, PCL shipped, PCL serial, the order
/// rotated each round) so a change of load during the run falls on all three alike.
Row measure(const std::string& name, const std::function<std::size_t()>& ours,
            const std::function<std::size_t()>& pcl) {
  Row row;
  row.name = name;
  std::vector<double> times[3];
  const auto run = [&](int contender) {
    if (contender > 0) {
      bench::set_openmp_regions(contender == 1 ? bench::OpenMpRegions::shipped
                                               : bench::OpenMpRegions::inline_serial);
    }
    const std::uint64_t regions_before = bench::openmp_regions_entered();
    const auto start = std::chrono::steady_clock::now();
    const std::size_t points = contender == 0 ? ours() : pcl();
    times[contender].push_back(seconds_since(start));
    if (contender == 0) row.ours_points = points;
    if (contender > 0) {
      if (row.pcl_points != 0 && row.pcl_points != points) {
        std::printf("  %s: PCL's point count differs between its modes (%zu, %zu)\n", name.c_str(),
                    row.pcl_points, points);
      }
      row.pcl_points = points;
      row.regions_per_call = static_cast<double>(bench::openmp_regions_entered() - regions_before);
    }
  };
  for (int round = 0; round < kRuns; ++round) {
    for (int i = 0; i < 3; ++i) run((round + i) % 3);
  }
  bench::set_openmp_regions(bench::OpenMpRegions::shipped);
  row.ours = median(times[0]);
  row.shipped = median(times[1]);
  row.serial = median(times[2]);
  return row;
}

void print(const std::string& cloud_name, std::size_t points, const std::vector<Row>& rows) {
  std::printf("\n%s (%zu points)\n", cloud_name.c_str(), points);
  std::printf("  %-24s %9s %9s %9s %8s %8s %9s %9s %9s\n", "stage", "ours ms", "PCL ms", "PCL1 ms",
              "PCL/ours", "PCL1/ours", "ours pts", "PCL pts", "regions");
  for (const Row& r : rows) {
    std::printf("  %-24s %9.2f %9.2f %9.2f %8.2f %9.2f %9zu %9zu %9.0f\n", r.name.c_str(),
                r.ours * 1e3, r.shipped * 1e3, r.serial * 1e3, r.shipped / r.ours,
                r.serial / r.ours, r.ours_points, r.pcl_points, r.regions_per_call);
  }
}

void compare(const std::string& name, const model::PointCloud& cloud) {
  const PclCloud::Ptr input = to_pcl(cloud);
  std::vector<Row> rows;
  const model::PointCloud voxelised = filters::voxel_grid(cloud);
  const PclCloud::Ptr pcl_voxelised = pcl_voxel(input, 0.03f);
  rows.push_back(measure(
      "voxel_grid 3 cm", [&] { return filters::voxel_grid(cloud).size(); },
      [&] { return pcl_voxel(input, 0.03f)->size(); }));
  rows.push_back(measure(
      "SOR on voxelised", [&] { return filters::statistical_outlier_removal(voxelised).size(); },
      [&] { return pcl_sor(pcl_voxelised)->size(); }));
  rows.push_back(measure(
      "pass_through z", [&] { return filters::pass_through(cloud).size(); },
      [&] { return pcl_pass(input, false)->size(); }));
  rows.push_back(measure(
      "RANSAC plane (voxelised)",
      [&] { return filters::fit_plane_ransac(voxelised).inliers.size(); },
      [&] {
        pcl::ModelCoefficients c;
        return pcl_plane(pcl_voxelised, c)->indices.size();
      }));
  rows.push_back(measure(
      "floor_removal_1", [&] { return filters::remove_floor_1(voxelised).size(); },
      [&] { return pcl_floor_1(pcl_voxelised)->size(); }));
  rows.push_back(measure(
      "floor_removal_2", [&] { return filters::remove_floor_2(voxelised).size(); },
      [&] { return pcl_floor_2(pcl_voxelised)->size(); }));
  rows.push_back(measure(
      "radius_outlier raw", [&] { return filters::radius_outlier_removal(cloud).size(); },
      [&] { return pcl_radius_outlier(input)->size(); }));
  rows.push_back(measure(
      "radius_outlier voxelised", [&] { return filters::radius_outlier_removal(voxelised).size(); },
      [&] { return pcl_radius_outlier(pcl_voxelised)->size(); }));
  for (const std::string pipeline : {"P2", "P3", "P4", "P2_paper2"}) {
    const model::Pipeline p = *filters::preset_pipeline(pipeline);
    // P2_paper2 on one frame: its throttle keeps it (the first of its stream), so the frame is
    // timed through radius outlier removal and the voxel grid.
    rows.push_back(measure(
        "pipeline " + pipeline, [&] { return filters::run_pipeline(p, cloud).size(); },
        [&] {
          if (pipeline == "P2_paper2") return pcl_voxel(pcl_radius_outlier(input), 0.03f)->size();
          const PclCloud::Ptr v = pcl_voxel(input, 0.03f);
          if (pipeline == "P2") return pcl_floor_1(pcl_sor(v))->size();
          if (pipeline == "P3") return pcl_sor(pcl_floor_1(v))->size();
          return pcl_floor_2(pcl_sor(v))->size();
        }));
  }
  print(name, cloud.size(), rows);
}

}  // namespace

// Usage: filters_vs_pcl_bench [cloud]  (a PCD file name, or "simulated"; default every cloud)
int main(int argc, char** argv) {
  const std::string only = argc > 1 ? argv[1] : "";
  const std::string folder = std::string(RIGDESIGN_SOURCE_DIR) + "/../shared/data/real";
  std::printf(
      "ours vs PCL %s, single thread, %d interleaved rounds per figure (medians).\n"
      "PCL: as shipped (an OpenMP region per neighbour query); PCL1: the same code with its\n"
      "OpenMP regions run inline on the calling thread (the fair peer); regions: PCL's OpenMP\n"
      "regions per call.\n",
      PCL_VERSION_PRETTY, kRuns);
  if (only.empty() || only == "simulated") {
    // A simulated Azure Kinect NFOV unbinned frame of the office, from the UR Cleaner's front.
    const model::SensorLibrary library =
        io::load_sensor_library(std::string(RIGDESIGN_SOURCE_DIR) + "/sensors.yaml");
    const model::Rig rig =
        io::load_rig(std::string(RIGDESIGN_SOURCE_DIR) + "/rigs/ur_cleaner.yaml");
    const model::Mount& front = rig.mounts.front();
    const model::SensorMode& mode = *library.find(front.sensor_id)->find_mode(front.mode_id);
    const model::PointCloud frame =
        sim::simulate_mount(sim::make_scene("office", 1), front, mode, 0, 1, 1).front();
    compare("simulated Azure Kinect NFOV frame, office scene (robot frame)", frame);
  }
  for (const char* file :
       {"office1.pcd", "five_people.pcd", "table_scene_mug_stereo_textured.pcd",
        "kinect_frame_20121214T142255.814212.pcd", "milk_cartoon_all_small_clorox.pcd"}) {
    if (!only.empty() && only != file) continue;
    const std::string path = folder + "/" + file;
    if (!std::filesystem::exists(path)) {
      std::printf("%s: not found, skipped\n", path.c_str());
      continue;
    }
    compare(file, bench::as_front_camera(io::read_cloud(path)));
  }
  return 0;
}
