#pragma once
/// URDF angles are radians. An <origin rpy="..."> component beyond +-2 pi is almost surely
/// degrees typed into the radians field (issue 30 item 7): urdfdom would take 90 as 90 rad
/// and place the link at a pose nobody meant, without a word.
#include "xml_tree.hpp"

namespace rigdesign::io {

/// Throws InputError at every <origin> (in the file and line it came from) whose rpy has a
/// component beyond +-2 pi, giving it in degrees as read and in radians as it would be.
void require_radian_origins(const xml::Node& robot);

}  // namespace rigdesign::io
