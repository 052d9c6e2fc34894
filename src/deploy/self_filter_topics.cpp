// The topics of the self-filter chains (self_filters.hpp), apart from the ray casting that
// finds the filters: the export writers name them, and are built without the simulator.
#include "rigdesign/deploy/self_filters.hpp"

namespace rigdesign::deploy {

std::string self_filtered_topic(const std::string& raw) {
  return raw + "_self_filtered";
}

std::string crop_box_topic(const std::string& raw, std::size_t k, std::size_t n) {
  return k >= n ? self_filtered_topic(raw) : raw + "_self_filter_" + std::to_string(k);
}

}  // namespace rigdesign::deploy
