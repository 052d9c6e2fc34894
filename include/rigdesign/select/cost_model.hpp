#pragma once
/// Paper 1's cost model, eqs. 1-7 (DESIGN.md section 5): C_s = sum of sensor prices;
/// B = sum of w_i f_i; C_t = the sum over the m transfer component kinds (eq. 4: cables,
/// switches, interfaces ...) of the cheapest component of each kind whose capacity exceeds B,
/// and for a kind bought per sensor (a cable, a port) the sum over the sensors of the cheapest
/// component whose capacity exceeds B_i;
/// U = sum of (U_p,i + U_f,i); C_c = the cheapest CPU whose capacity exceeds U;
/// C = C_s + C_t + C_c.
#include <string>
#include <vector>

#include "rigdesign/model/catalog.hpp"

namespace rigdesign::select {

/// What a rig asks of the hardware.
struct RigLoad {
  double sensor_cost = 0.0;  ///< C_s [USD]
  double bandwidth = 0.0;    ///< B [bytes/s]
  double cpu = 0.0;          ///< U [core-equivalents]
  int sensors = 0;
  /// The per-sensor transfer components of the sensors so far [USD] (per_sensor_transfer):
  /// additive, as C_s is, so the search adds each option's own.
  double per_sensor_transfer = 0.0;
};

struct CostBreakdown {
  bool feasible = false;  ///< some transfer item and some CPU carry the load
  double sensors = 0.0;   ///< C_s
  double transfer = 0.0;  ///< C_t
  double cpu = 0.0;       ///< C_c
  double total = 0.0;     ///< C
  std::string transfer_id;
  std::string cpu_id;
};

/// The cheapest item whose capacity exceeds `load` (same unit as the capacity), or nullptr.
const model::PricedCapacity* cheapest_exceeding(const std::vector<model::PricedCapacity>& items,
                                                double load);

/// Of each kind of `items` (contiguous runs of one `kind`), the cheapest whose capacity exceeds
/// `load`; empty when some kind has none (or there are no items).
std::vector<const model::PricedCapacity*> cheapest_per_kind(
    const std::vector<model::PricedCapacity>& items, double load);

/// The price of the per-sensor transfer components (per_sensor kinds of `items`) one sensor
/// sending `bandwidth` [bytes/s] needs: per such kind the cheapest whose capacity exceeds it.
/// +infinity when a kind has none that does; 0 without per-sensor kinds.
double per_sensor_transfer_price(const std::vector<model::PricedCapacity>& items, double bandwidth);

/// C for a load; transfer capacities are bit/s and the bandwidth bytes/s. transfer_id names
/// each shared kind's component, joined by " + ", and the per-sensor kinds ("per sensor:
/// cable"); their price is the load's per_sensor_transfer.
CostBreakdown rig_cost(const RigLoad& load, const std::vector<model::PricedCapacity>& transfer,
                       const std::vector<model::PricedCapacity>& cpus);

/// rig_cost(...).total, or +infinity when no item carries the load: the search's inner loop,
/// without the breakdown's strings.
double total_cost(const RigLoad& load, const std::vector<model::PricedCapacity>& transfer,
                  const std::vector<model::PricedCapacity>& cpus);

}  // namespace rigdesign::select
