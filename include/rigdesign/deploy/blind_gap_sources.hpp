#pragma once
/// Which observation sources keep their clouds for the blind gaps (issue 30 item 2): nav2 has
/// no Hit Layer, so a source that sees an obstacle on its way into a gap keeps each cloud for
/// the gap's persistence (deploy/blind_memory.hpp: hit_max / f seconds). The test: the source
/// measures some height of an obstacle one cell (5 cm) outside the body on its approach, from
/// the distance of interest to where it is seen last before the gap (BlindGap::last_seen), on
/// that side, sampled every 5 cm. A gap no source sees on its approach gets a warning note.
#include "rigdesign/deploy/costmap_config.hpp"
#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::deploy {

/// Sets each source's observation_persistence in `config` (sources in mount order, memory
/// already sized from `coverage`) and adds the notes that say which and why. With `stvl` the
/// 3D sources remember through spatio_temporal_voxel_layer's voxel_decay instead, and the
/// note says so.
void keep_blind_gap_clouds(const model::Rig& rig, const model::SensorLibrary& library,
                           const metrics::RigCoverage& coverage, CostmapConfig& config,
                           bool stvl = false);

}  // namespace rigdesign::deploy
