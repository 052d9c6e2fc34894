#pragma once
// The catalog's CPU and transfer as limits on a rig (paper 1, eqs. 4-6): the load a search's
// rig puts on them, the most they carry, and the same problem with them free and unlimited,
// which is how `select` tells a rig the requirements rule out from one the hardware does.
#include <string>
#include <vector>

#include "rigdesign/select/cost_model.hpp"
#include "rigdesign/select/search.hpp"

namespace rigdesign::select {

/// The CPU load, bandwidth, sensor cost (sensors and supports) and per-sensor transfer price
/// of a search's rig.
RigLoad load_of(const SearchProblem& problem, const SearchResult& result);

/// The largest capacity of `items`; `id` names its item (unchanged when there is none).
double largest_capacity(const std::vector<model::PricedCapacity>& items, std::string& id);

/// The most a rig can send [bit/s]: each shared transfer kind carries up to its largest item
/// (eq. 4 buys one of each), so the kind whose largest item is smallest bounds it; `id` names
/// that item. +infinity when only per-sensor kinds (or none) exist.
double transfer_bottleneck(const std::vector<model::PricedCapacity>& items, std::string& id);

/// One free item of unlimited capacity: a CPU or transfer list that carries any load.
std::vector<model::PricedCapacity> unlimited_capacity();

/// `problem` with one free CPU and one free transfer item of unlimited capacity and no
/// per-sensor transfer price: its cost is the sensors' alone.
SearchProblem with_unlimited_hardware(const SearchProblem& problem);

}  // namespace rigdesign::select
