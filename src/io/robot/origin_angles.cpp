#include "origin_angles.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::io {
namespace {

constexpr double kFullTurn = 2 * std::numbers::pi;

void check_element(const xml::Node& node, model::Diagnostics& findings) {
  if (node.is_element("origin")) {
    if (const std::string* rpy = node.attribute("rpy")) {
      std::istringstream numbers(*rpy);
      std::vector<double> values;
      for (double value = 0.0; numbers >> value;) values.push_back(value);
      bool beyond = false;
      std::string as_degrees;
      for (const double value : values) {
        beyond = beyond || std::abs(value) > kFullTurn;
        as_degrees +=
            (as_degrees.empty() ? "" : " ") + model::format_number(model::deg_to_rad(value), 4);
      }
      if (beyond) {
        findings.error(node.where, "origin.rpy",
                       "looks like degrees: '" + *rpy + "' has an angle beyond +-2 pi rad",
                       "radians (as degrees these would be " + as_degrees + " rad)");
      }
    }
  }
  for (const xml::Node& child : node.children) check_element(child, findings);
}

}  // namespace

void require_radian_origins(const xml::Node& robot) {
  model::Diagnostics findings;
  check_element(robot, findings);
  findings.throw_if_errors();
}

}  // namespace rigdesign::io
