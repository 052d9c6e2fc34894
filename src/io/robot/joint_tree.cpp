#include "joint_tree.hpp"

#include <map>
#include <set>

#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {
namespace {

struct JointLinks {
  std::string name;
  std::string parent;
  std::string child;
  model::SourceLocation where;
};

const std::string* link_of(const xml::Node& joint, const std::string& tag) {
  for (const xml::Node& part : joint.children) {
    if (part.is_element(tag)) return part.attribute("link");
  }
  return nullptr;
}

std::string field_of(const JointLinks& joint) {
  return "joint '" + joint.name + "'";
}

std::string line_of(const model::SourceLocation& where) {
  return where.line > 0 ? " (line " + std::to_string(where.line) + ")" : std::string();
}

}  // namespace

void require_joint_tree(const xml::Node& robot) {
  const std::string kTree =
      "joints that join the links into one tree: no link is the child "
      "of two joints, none is its own ancestor";
  std::map<std::string, JointLinks> joint_of_child;
  for (const xml::Node& element : robot.children) {
    if (!element.is_element("joint")) continue;
    const std::string* parent = link_of(element, "parent");
    const std::string* child = link_of(element, "child");
    if (!parent || !child) continue;
    const std::string* name = element.attribute("name");
    const JointLinks joint{name ? *name : std::string(), *parent, *child, element.where};
    if (joint.parent == joint.child) {
      throw model::InputError(model::Diagnostic{joint.where, field_of(joint) + ".child",
                                                "is '" + joint.child + "', its own parent link",
                                                kTree});
    }
    const auto [earlier, inserted] = joint_of_child.emplace(joint.child, joint);
    if (!inserted) {
      throw model::InputError(
          model::Diagnostic{joint.where, field_of(joint) + ".child",
                            "link '" + joint.child + "' is already the child of joint '" +
                                earlier->second.name + "'" + line_of(earlier->second.where),
                            kTree});
    }
  }
  // Each link has at most one parent now: walking up from every link must end at a root
  // (or at a link already known to reach one, which keeps the walk linear).
  std::set<std::string> reaches_root;
  for (const auto& [start, first_joint] : joint_of_child) {
    std::set<std::string> seen{start};
    for (auto up = joint_of_child.find(first_joint.parent);
         up != joint_of_child.end() && !reaches_root.contains(up->first);
         up = joint_of_child.find(up->second.parent)) {
      if (!seen.insert(up->first).second) {
        throw model::InputError(
            model::Diagnostic{up->second.where, field_of(up->second) + ".parent",
                              "closes a loop: link '" + up->second.parent +
                                  "' is a descendant of link '" + up->first + "'",
                              kTree});
      }
    }
    reaches_root.merge(seen);
  }
}

}  // namespace rigdesign::io
