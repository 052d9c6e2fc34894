#include "rigdesign/select/cost_model.hpp"

#include <limits>

#include "rigdesign/model/format_number.hpp"

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

std::vector<const model::PricedCapacity*> cheapest_per_kind(
    const std::vector<model::PricedCapacity>& items, double load) {
  std::vector<const model::PricedCapacity*> chosen;
  for (std::size_t begin = 0; begin < items.size();) {
    std::size_t end = begin;
    const model::PricedCapacity* best = nullptr;
    for (; end < items.size() && items[end].kind == items[begin].kind; ++end) {
      if (items[end].capacity > load && (best == nullptr || items[end].price < best->price))
        best = &items[end];
    }
    if (best == nullptr) return {};  // this kind carries no such load: nothing does
    chosen.push_back(best);
    begin = end;
  }
  return chosen;
}

CostBreakdown rig_cost(const RigLoad& load, const std::vector<model::PricedCapacity>& transfer,
                       const std::vector<model::PricedCapacity>& cpus) {
  CostBreakdown cost;
  cost.sensors = load.sensor_cost;
  const std::vector<const model::PricedCapacity*> links =
      cheapest_per_kind(transfer, load.bandwidth * kBitsPerByte);
  const model::PricedCapacity* cpu = cheapest_exceeding(cpus, load.cpu);
  cost.feasible = !links.empty() && cpu != nullptr;
  std::vector<std::string> ids;
  for (const model::PricedCapacity* link : links) {
    cost.transfer += link->price;
    ids.push_back(link->id);
  }
  cost.transfer_id = model::join(ids, " + ");
  if (cpu != nullptr) {
    cost.cpu = cpu->price;
    cost.cpu_id = cpu->id;
  }
  cost.total = cost.sensors + cost.transfer + cost.cpu;
  return cost;
}

double total_cost(const RigLoad& load, const std::vector<model::PricedCapacity>& transfer,
                  const std::vector<model::PricedCapacity>& cpus) {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  const model::PricedCapacity* cpu = cheapest_exceeding(cpus, load.cpu);
  if (cpu == nullptr) return kNone;
  // Eq. 4 without the vector: per kind (contiguous) the cheapest item above the bandwidth.
  const double bits = load.bandwidth * kBitsPerByte;
  double transfer_cost = 0.0;
  for (std::size_t begin = 0; begin < transfer.size();) {
    double best = kNone;
    std::size_t end = begin;
    for (; end < transfer.size() && transfer[end].kind == transfer[begin].kind; ++end) {
      if (transfer[end].capacity > bits && transfer[end].price < best) best = transfer[end].price;
    }
    if (best == kNone) return kNone;
    transfer_cost += best;
    begin = end;
  }
  if (transfer.empty()) return kNone;
  return load.sensor_cost + transfer_cost + cpu->price;
}

}  // namespace rigdesign::select
