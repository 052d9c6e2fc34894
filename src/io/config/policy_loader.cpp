#include "rigdesign/io/config/policy_loader.hpp"

#include "rigdesign/io/config/field_checks.hpp"
#include "rigdesign/io/config/yaml_reader.hpp"

namespace rigdesign::io {

model::RelaxationPolicy load_policy(const std::string& path) {
  model::Diagnostics diagnostics;
  MapReader top =
      read_document_map(path, diagnostics, "a relaxation policy: a map with name and steps");
  model::RelaxationPolicy policy;
  policy.file = path;
  policy.name = top.text("name", io::Need::required, "the policy's name").value_or("");
  for (io::MapReader& reader : top.maps("steps", io::Need::required, "a list of steps")) {
    model::RelaxationStep step;
    step.where = reader.location();
    step.requirement =
        reader.text("relax", io::Need::required, "a requirement path such as robot_speed.max_speed")
            .value_or("");
    if (step.requirement == "lighting") {
      step.drop = io::named_value(reader, "drop", io::Need::required, model::kLightConditionNames);
    } else {
      step.to = reader.number("to", io::Need::required,
                              "the relaxed value as a plain number in SI units (m, m/s, Hz) or a "
                              "share in [0, 1]");
    }
    reader.text("note", io::Need::optional);
    reader.reject_unknown_keys();
    policy.steps.push_back(std::move(step));
  }
  top.text("note", io::Need::optional);
  top.reject_unknown_keys();
  diagnostics.throw_if_errors();
  return policy;
}

}  // namespace rigdesign::io
