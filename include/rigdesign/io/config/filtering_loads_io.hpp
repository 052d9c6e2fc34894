#pragma once
/// The filtering-loads file (rigs/README.md): read with located errors, written in the form
/// it is read back in.
#include <string>

#include "rigdesign/model/filtering_loads.hpp"

namespace rigdesign::io {

/// Throws InputError naming file:line:col and the field on bad input.
model::FilteringLoads load_filtering_loads(const std::string& path);

/// YAML text; `comment` becomes the header comment, one "# " line per line.
std::string filtering_loads_to_yaml(const model::FilteringLoads& loads, const std::string& comment);

/// `measured` merged over `previous`: sensors measured now replace their earlier entries, the
/// others are kept (so a file can collect loads from several rigs).
model::FilteringLoads merge_filtering_loads(const model::FilteringLoads& previous,
                                            const model::FilteringLoads& measured);

}  // namespace rigdesign::io
