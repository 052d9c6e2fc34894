#include "select/hardware_limits.hpp"

#include <limits>

namespace rigdesign::select {
namespace {

constexpr double kNoLimit = std::numeric_limits<double>::infinity();

}  // namespace

RigLoad load_of(const SearchProblem& problem, const SearchResult& result) {
  RigLoad load;
  for (std::size_t k = 0; k < result.choice.size(); ++k) {
    if (result.choice[k] < 0) continue;
    const SearchOption& option = problem.slots[k][result.choice[k]];
    load.cpu += option.cpu;
    load.bandwidth += option.bandwidth;
    load.per_sensor_transfer += option.transfer_price;
    load.sensor_cost += option.price;
    ++load.sensors;
  }
  return load;
}

double largest_capacity(const std::vector<model::PricedCapacity>& items, std::string& id) {
  double largest = 0.0;
  for (const model::PricedCapacity& item : items) {
    if (item.capacity > largest) {
      largest = item.capacity;
      id = item.id;
    }
  }
  return largest;
}

// Kinds bought per sensor bound each sensor, not the rig (their prices are the options').
double transfer_bottleneck(const std::vector<model::PricedCapacity>& items, std::string& id) {
  double bottleneck = kNoLimit;
  bool first = true;
  for (std::size_t begin = 0; begin < items.size();) {
    std::size_t end = begin;
    while (end < items.size() && items[end].kind == items[begin].kind) ++end;
    if (items[begin].per_sensor) {
      begin = end;
      continue;
    }
    std::string kind_id;
    const double largest = largest_capacity(
        std::vector<model::PricedCapacity>(items.begin() + static_cast<std::ptrdiff_t>(begin),
                                           items.begin() + static_cast<std::ptrdiff_t>(end)),
        kind_id);
    if (first || largest < bottleneck) {
      bottleneck = largest;
      id = kind_id;
      first = false;
    }
    begin = end;
  }
  return bottleneck;
}

std::vector<model::PricedCapacity> unlimited_capacity() {
  return {{"unlimited", kNoLimit, 0.0, {}, {}}};
}

SearchProblem with_unlimited_hardware(const SearchProblem& problem) {
  SearchProblem unlimited = problem;
  unlimited.transfer = unlimited_capacity();
  unlimited.cpus = unlimited_capacity();
  for (std::vector<SearchOption>& slot : unlimited.slots)
    for (SearchOption& option : slot) option.transfer_price = 0.0;  // per-sensor cables too
  return unlimited;
}

}  // namespace rigdesign::select
