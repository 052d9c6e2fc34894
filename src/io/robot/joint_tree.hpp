#pragma once
/// The joints of a URDF must join its links into a tree. urdfdom links each parent to its
/// children with owning pointers before it checks for a root, so a joint whose child is its
/// own parent, or joints that close a loop, leave a reference cycle that is never freed (and
/// its message names neither the joint nor the line). This check runs on the XML first.
#include "xml_tree.hpp"

namespace rigdesign::io {

/// Throws InputError at the offending <joint> when a joint's child is its parent, a link is
/// the child of two joints, or the joints close a loop. Joints without a parent or child
/// link are left for urdfdom to report.
void require_joint_tree(const xml::Node& robot);

}  // namespace rigdesign::io
