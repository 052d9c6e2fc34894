#pragma once
/// Spatial Coverage (paper 1, section 2.3, Fig. 2; DESIGN.md section 4): for every azimuth
/// theta, the share of the cross-section [r, d] x [0, h] that the rig sees (SC complete) and
/// the share of its floor segment (SC floor), with summaries overall and per requirement
/// sector, plus what existing tools do not report: per-angle worst ray spacing and noise
/// among the sensors covering the angle, a redundancy curve and an N-1 table.
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/geometry/section_polygons.hpp"
#include "rigdesign/geometry/section_raster.hpp"
#include "rigdesign/model/requirements.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::metrics {

struct CoverageSettings {
  double step = 0.017453292519943295;  ///< [rad] between sampled azimuths (1 degree)
  bool exact = true;                   ///< SC curves from CGAL polygons (else from the raster)
  geometry::TessellationSettings tessellation;
  double raster_cell = 0.01;  ///< [m] raster cell size along rho and z
};

/// A coverage share counts as 100 % from here: the exact path's topology gaps (min_gap wide)
/// keep a fully covered section a few 1e-5 short of 1.
inline constexpr double kFullCoverage = 1.0 - 1e-4;

/// A share as verdicts judge it: 1 from kFullCoverage on (a fully covered section), else the
/// share itself, unrounded. Requirements compare this value with `>=`, and reports print it,
/// so a verdict and the sign of its margin always agree.
inline double judged_share(double share) {
  return share >= kFullCoverage ? 1.0 : share;
}

struct AngleCoverage {
  double theta = 0.0;     ///< [rad]
  double r = 0.0;         ///< [m] body radius along theta
  double complete = 0.0;  ///< SC complete, share in [0, 1]
  double floor = 0.0;     ///< SC floor
  double complete_raster = 0.0;
  double floor_raster = 0.0;
  double redundancy = 0.0;  ///< share of the cross-section seen by two or more sensors (raster)
  std::vector<bool> mount_sees;  ///< per mount: sees part of this cross-section
  /// Per mount, its own SC complete and floor here (raster): which mount a sector's verdict
  /// rests on (issue 39: CI annotations on the mount's line).
  std::vector<double> mount_complete;
  std::vector<double> mount_floor;
  int coarsest_mount = -1;        ///< index of the covering mount with the widest ray spacing
  double coarsest_spacing = 0.0;  ///< [m] its spacing at its distance of interest
  int noisiest_mount = -1;
  double noisiest_noise = 0.0;  ///< [m]
};

struct CoverageSummary {
  double min = 0.0;
  double mean = 0.0;
  double full_share = 0.0;  ///< share of angles at 100 %
  double min_theta = 0.0;   ///< [rad] where the minimum is
};

struct SectorCoverage {
  model::SectorRequirement sector;
  CoverageSummary complete;
  CoverageSummary floor;
  /// judged_share(complete.min) >= min_complete_coverage and likewise for the floor.
  bool pass = false;
};

/// The one of a sector's two requirements (SC complete, SC floor) with the smaller margin:
/// what its verdict rests on. `floor` says which; shares as judged_share gives them.
struct BindingShare {
  bool floor = false;
  double actual = 0.0;
  double required = 0.0;
};
BindingShare binding_share(const SectorCoverage& coverage);

/// SC summaries with one mount removed (N-1), from the raster path.
struct MountLoss {
  std::string mount_id;
  CoverageSummary complete;
  CoverageSummary floor;
};

struct RigCoverage {
  std::vector<std::string> mount_ids;
  std::vector<std::string> mount_sensors;  ///< per mount, its sensor id (pictures' legends)
  double distance = 0.0;                   ///< d [m]
  double height = 0.0;                     ///< h [m]
  std::vector<AngleCoverage> angles;
  CoverageSummary complete;
  CoverageSummary floor;
  std::vector<SectorCoverage> sectors;
  std::vector<MountLoss> without_each;
  /// The whole rig on the raster path, the baseline `without_each` is compared with: the
  /// exact path's means differ from the raster's by up to raster_error, so a row of N-1 set
  /// against the exact summary could show a loss as a gain.
  CoverageSummary complete_raster;
  CoverageSummary floor_raster;
  double raster_error_complete = 0.0;  ///< largest |exact - raster| over angles
  double raster_error_floor = 0.0;
  bool exact = true;
};

/// Precondition: the rig's references resolve (check_rig_references) and no mount is inside
/// the body. Deterministic.
RigCoverage compute_coverage(const model::Rig& rig, const model::SensorLibrary& library,
                             const std::vector<model::SectorRequirement>& sectors,
                             const CoverageSettings& settings = {});

/// One cross-section in full, for pictures: each mount's region as polygons and its floor
/// intervals, and the union's shares (exact path).
struct SectionView {
  geometry::SectionFrame frame;
  std::vector<std::string> mount_ids;
  std::vector<std::string> mount_sensors;                 ///< per mount, its sensor id
  std::vector<std::vector<geometry::Polygon2>> polygons;  ///< per mount, (rho, z)
  std::vector<geometry::IntervalSet> floors;              ///< per mount, rho intervals at z = 0
  std::vector<model::Vec3> origins;  ///< per mount, sensor origin (robot frame)
  double complete = 0.0;
  double floor = 0.0;
};

SectionView section_view(const model::Rig& rig, const model::SensorLibrary& library, double theta,
                         const geometry::TessellationSettings& tessellation = {});

/// Whether azimuth `theta` lies in the sector (angles compared modulo 360 degrees).
bool in_sector(const model::SectorRequirement& sector, double theta);

}  // namespace rigdesign::metrics
