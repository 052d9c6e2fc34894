#pragma once
// A small valid sensor library, rig and requirement set, written into a temporary folder.
// Bad-input tests change one thing in them at a time.
#include <string>

namespace rigdesign::test {

inline const std::string kLibrary = R"(reference_machine: test machine
sensors:
  - id: cam
    name: Camera
    technology: tof
    source: test datasheet
    price: {usd: 100, year: 2020, basis: estimate, source: test}
    modes:
      - id: m30
        fov: {shape: pyramid, horizontal_deg: 60, vertical_deg: 40}
        range: {min: 0.1, max: 4.0}
        frequency: 30
        pixels: [320, 240]
        bytes_per_point: 2
        noise: {a: 0.01}
        light: {dark: true, indoor: true, sunlight: false}
        driver_cpu: {cores: 0.1, basis: estimate}
  - id: spin
    name: Spinner
    technology: lidar_3d_spinning
    source: test datasheet
    price: {usd: 1000, year: 2020, basis: estimate, source: test}
    modes:
      - id: s10
        fov: {shape: band, horizontal_deg: 360, elevation_min_deg: -15, elevation_max_deg: 15}
        range: {min: 0.5, max: 50}
        frequency: 10
        angular_resolution_deg: [0.2, 2.0]
        points_per_frame: 28800
        bytes_per_second: 900000
        noise: {a: 0.03}
        light: {dark: true, indoor: true, sunlight: true}
        driver_cpu: {cores: 0.05, basis: estimate}
)";

inline const std::string kRig = R"(name: Test rig
sensor_library: sensors.yaml
requirements: req.yaml
body:
  radius: 0.4
  height: 1.0
distance_of_interest: 3.0
mounts:
  - id: front
    sensor: cam
    mode: m30
    pose: {xyz: [0.41, 0.0, 0.5], rpy_deg: [0, 20, 0]}
  - id: top
    sensor: spin
    mode: s10
    pose: {xyz: [0.0, 0.0, 1.05], rpy_deg: [0, 0, 0]}
)";

// With kRig: F = 10 Hz >= 1 / 0.1; R = 3 m * tan 2 deg = 104.8 mm <= 150 mm;
// N = 30 mm <= 50 mm; both sensors work in the dark and indoors.
inline const std::string kRequirements = R"(name: Test application
body: {radius: 0.4, height: 1.0}
sectors:
  - {name: front, from_deg: -45, to_deg: 45, min_complete_coverage: 0.1, min_floor_coverage: 0.0}
range: {distance: 3.0}
robot_speed: {max_speed: 1.0, max_travel_between_frames: 0.1}
smallest_obstacle: {size: 0.15}
accuracy: {max_noise: 0.05}
lighting: [dark, indoor]
)";

}  // namespace rigdesign::test
