#include "rigdesign/select/cost_model.hpp"

#include <limits>

namespace rigdesign::select {

namespace {
constexpr double kBitsPerByte = 8.0;
}  // namespace

const model::PricedCapacity* cheapest_exceeding(const std::vector<model::PricedCapacity>& items,
                                                double load) {
  const model::PricedCapacity* best = nullptr;
  for (const model::PricedCapacity& item : items) {
    if (item.capacity > load && (best == nullptr || item.price < best->price)) best = &item;
  }
  return best;
}

CostBreakdown rig_cost(const RigLoad& load, const std::vector<model::PricedCapacity>& transfer,
                       const std::vector<model::PricedCapacity>& cpus) {
  CostBreakdown cost;
  cost.sensors = load.sensor_cost;
  const model::PricedCapacity* link = cheapest_exceeding(transfer, load.bandwidth * kBitsPerByte);
  const model::PricedCapacity* cpu = cheapest_exceeding(cpus, load.cpu);
  cost.feasible = link != nullptr && cpu != nullptr;
  if (link != nullptr) {
    cost.transfer = link->price;
    cost.transfer_id = link->id;
  }
  if (cpu != nullptr) {
    cost.cpu = cpu->price;
    cost.cpu_id = cpu->id;
  }
  cost.total = cost.sensors + cost.transfer + cost.cpu;
  return cost;
}

double total_cost(const RigLoad& load, const std::vector<model::PricedCapacity>& transfer,
                  const std::vector<model::PricedCapacity>& cpus) {
  const model::PricedCapacity* link = cheapest_exceeding(transfer, load.bandwidth * kBitsPerByte);
  const model::PricedCapacity* cpu = cheapest_exceeding(cpus, load.cpu);
  if (link == nullptr || cpu == nullptr) return std::numeric_limits<double>::infinity();
  return load.sensor_cost + link->price + cpu->price;
}

}  // namespace rigdesign::select
