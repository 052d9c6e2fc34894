#include "rigdesign/costmap/hit_layer.hpp"

#include <algorithm>
#include <stdexcept>

#include "rigdesign/costmap/cost_values.hpp"

namespace rigdesign::costmap {

void apply_hit_equations(std::span<const std::uint8_t> observed, std::span<std::uint16_t> counts,
                         const HitLayerParams& params, bool decrement, std::uint8_t occupied) {
  if (observed.size() != counts.size()) {
    throw std::invalid_argument("apply_hit_equations: the grids differ in size");
  }
  // Counts fit in 16 bits (check_costmap_params caps hit_max), so the sum does in 32.
  const auto hit = static_cast<std::uint32_t>(params.hit);
  const auto hit_max = static_cast<std::uint32_t>(params.hit_max);
  const std::uint32_t down = decrement ? 1u : 0u;
  const std::size_t n = counts.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t h = counts[i];
    const std::uint32_t raised = std::min(h + hit, hit_max);  // paper 1, eq. (8)
    const std::uint32_t lowered = h - std::min(h, down);      // paper 1, eq. (9)
    counts[i] = static_cast<std::uint16_t>(observed[i] == occupied ? raised : lowered);
  }
}

void MotionMonitor::record(double time, const model::Vec2& position_world) {
  samples_.push_back({time, position_world});
  // Keep the samples of the last d_duration seconds (and the newest, whatever its age).
  while (samples_.size() > 1 && samples_.front().time < time - params_.d_duration)
    samples_.pop_front();
}

bool MotionMonitor::moving(bool velocity_command) const {
  if (velocity_command) return true;
  if (samples_.empty()) return false;
  const model::Vec2& now = samples_.back().position;
  return std::any_of(samples_.begin(), samples_.end(), [&](const Sample& sample) {
    return (sample.position - now).norm() >= params_.d_threshold;
  });
}

HitLayer::HitLayer(const GridWindow& window, const HitLayerParams& params)
    : params_(params), motion_(params), counts_(window, 0) {}

bool HitLayer::update(const CostGrid& obstacles, double time, const model::Vec2& robot_world,
                      bool velocity_command) {
  if (obstacles.window().origin_cell != counts_.window().origin_cell) {
    throw std::invalid_argument("HitLayer::update: the obstacle grid is on another window");
  }
  motion_.record(time, robot_world);
  const bool decrement = motion_.moving(velocity_command);
  apply_hit_equations(obstacles.cells(), counts_.cells(), params_, decrement);
  return decrement;
}

void HitLayer::mark(CostGrid& master) const {
  const std::vector<std::uint16_t>& h = counts_.cells();
  std::vector<std::uint8_t>& cells = master.cells();
  if (cells.size() != h.size())
    throw std::invalid_argument("HitLayer::mark: the master grid differs in size");
  for (std::size_t i = 0; i < h.size(); ++i) {
    if (h[i] > 0) cells[i] = cost::kLethal;
  }
}

}  // namespace rigdesign::costmap
