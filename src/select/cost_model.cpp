#include "rigdesign/select/cost_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rigdesign/model/format_number.hpp"

namespace rigdesign::select {

namespace {
constexpr double kBitsPerByte = 8.0;
}  // namespace

namespace {

// The end of the run of items of one kind starting at `begin` (items of a kind are contiguous).
std::size_t kind_end(const std::vector<model::PricedCapacity>& items, std::size_t begin) {
  std::size_t end = begin;
  while (end < items.size() && items[end].kind == items[begin].kind) ++end;
  return end;
}

// The cheapest item of items[begin, end) whose capacity exceeds `load`, or nullptr.
const model::PricedCapacity* cheapest_in(const std::vector<model::PricedCapacity>& items,
                                         std::size_t begin, std::size_t end, double load) {
  const model::PricedCapacity* best = nullptr;
  for (std::size_t i = begin; i < end; ++i) {
    if (items[i].capacity > load && (best == nullptr || items[i].price < best->price))
      best = &items[i];
  }
  return best;
}

}  // namespace

const model::PricedCapacity* cheapest_exceeding(const std::vector<model::PricedCapacity>& items,
                                                double load) {
  return cheapest_in(items, 0, items.size(), load);
}

std::vector<const model::PricedCapacity*> cheapest_per_kind(
    const std::vector<model::PricedCapacity>& items, double load) {
  std::vector<const model::PricedCapacity*> chosen;
  for (std::size_t begin = 0; begin < items.size();) {
    const std::size_t end = kind_end(items, begin);
    if (!items[begin].per_sensor) {
      const model::PricedCapacity* best = cheapest_in(items, begin, end, load);
      if (best == nullptr) return {};  // this kind carries no such load: nothing does
      chosen.push_back(best);
    }
    begin = end;
  }
  return chosen;
}

double per_sensor_transfer_price(const std::vector<model::PricedCapacity>& items,
                                 double bandwidth) {
  double price = 0.0;
  for (std::size_t begin = 0; begin < items.size();) {
    const std::size_t end = kind_end(items, begin);
    if (items[begin].per_sensor) {
      const model::PricedCapacity* best = cheapest_in(items, begin, end, bandwidth * kBitsPerByte);
      if (best == nullptr) return std::numeric_limits<double>::infinity();
      price += best->price;
    }
    begin = end;
  }
  return price;
}

CostBreakdown rig_cost(const RigLoad& load, const std::vector<model::PricedCapacity>& transfer,
                       const std::vector<model::PricedCapacity>& cpus) {
  CostBreakdown cost;
  cost.sensors = load.sensor_cost;
  const std::vector<const model::PricedCapacity*> links =
      cheapest_per_kind(transfer, load.bandwidth * kBitsPerByte);
  const model::PricedCapacity* cpu = cheapest_exceeding(cpus, load.cpu);
  const bool any_shared = std::any_of(transfer.begin(), transfer.end(),
                                      [](const model::PricedCapacity& t) { return !t.per_sensor; });
  cost.feasible = !transfer.empty() && (!links.empty() || !any_shared) && cpu != nullptr &&
                  std::isfinite(load.per_sensor_transfer);
  std::vector<std::string> ids;
  for (const model::PricedCapacity* link : links) {
    cost.transfer += link->price;
    ids.push_back(link->id);
  }
  for (std::size_t begin = 0; begin < transfer.size(); begin = kind_end(transfer, begin))
    if (transfer[begin].per_sensor) ids.push_back("per sensor: " + transfer[begin].kind);
  cost.transfer += load.per_sensor_transfer;
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
  if (transfer.empty()) return kNone;
  const model::PricedCapacity* cpu = cheapest_exceeding(cpus, load.cpu);
  if (cpu == nullptr) return kNone;
  // Eq. 4 without the vector: per shared kind the cheapest item above the bandwidth; the
  // per-sensor kinds' price came with each sensor (load.per_sensor_transfer).
  const double bits = load.bandwidth * kBitsPerByte;
  double transfer_cost = load.per_sensor_transfer;
  for (std::size_t begin = 0; begin < transfer.size();) {
    const std::size_t end = kind_end(transfer, begin);
    if (!transfer[begin].per_sensor) {
      const model::PricedCapacity* best = cheapest_in(transfer, begin, end, bits);
      if (best == nullptr) return kNone;
      transfer_cost += best->price;
    }
    begin = end;
  }
  return load.sensor_cost + transfer_cost + cpu->price;
}

}  // namespace rigdesign::select
