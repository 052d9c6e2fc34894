#pragma once
/// Where two mounts see the same points (issue 38: crosstalk between active sensors and the
/// overlap extrinsic calibration needs). The area to perceive (rho from the body's outline
/// r(theta) to the distance given, z from the floor to the area's top) is cut into vertical
/// columns on a polar grid; in each column every mount's seen z intervals are exact
/// (geometry::column_coverage: FOV, range and the body's shadow). Three areas per pair, each the
/// floor area of the columns that count, weighted by their polar area rho * dtheta * drho (so
/// they converge to the exact ones as the grid refines): columns where both see some point (an
/// upright target standing there is seen by both: what calibration registers), columns where
/// their intervals intersect (a point seen, or lit, by both: what crosstalk needs), and columns
/// whose floor point both see.
#include <string>
#include <vector>

#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::metrics {

struct CovisibilitySettings {
  double step = 0.017453292519943295;  ///< [rad] between column azimuths (1 degree)
  double radial = 0.05;                ///< [m] largest column depth along rho
};

struct PairOverlap {
  std::size_t a = 0;  ///< mount indices in the rig, a < b
  std::size_t b = 0;
  double column_area = 0.0;  ///< [m^2] columns in which both see something
  double area = 0.0;         ///< [m^2] columns in which both see a common point
  double floor_area = 0.0;   ///< [m^2] floor both see
};

struct Covisibility {
  std::vector<std::string> mount_ids;
  std::vector<PairOverlap> pairs;  ///< every pair a < b, in order (0,1), (0,2), ..., (1,2), ...
  double distance = 0.0;           ///< [m] the outer edge of the area searched
  double height = 0.0;             ///< [m] its top
};

/// The distance out to which crosstalk and calibration overlap are searched: the rig's
/// distance of interest, or a mount's own where it is larger [m].
double covisibility_distance(const model::Rig& rig);

/// Every pair of the rig's mounts over the area out to `distance` from the robot's axis.
/// Precondition as compute_coverage. Deterministic (columns on every core, summed in order).
Covisibility covisibility(const model::Rig& rig, const model::SensorLibrary& library,
                          double distance, const CovisibilitySettings& settings = {});

}  // namespace rigdesign::metrics
