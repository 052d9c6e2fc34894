#pragma once
/// The links of the walking person (sim's person_mesh) and the volume paper 3 builds round
/// each to find the actor's points (section III-B, eqs. 1-4, as ../shared/DESIGN.md section 9
/// states them: "cylinders, e.g. r = 0.1 m shoulder to elbow; prisms, e.g. 0.2 x 0.3 m spine
/// to lower back"). In the person's own frame: x forward, y left, z up, feet at z = 0.
#include <string>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::sim {

enum class LinkShape {
  cylinder,  ///< every point within `radius` of the segment start-end
  prism,     ///< a box along the segment, `width` across the body (y), `depth` front-back (x)
};

struct BodyLink {
  std::string name;
  model::Vec3 start;  ///< [m] the joint the link hangs from
  model::Vec3 end;    ///< [m]
  LinkShape shape = LinkShape::cylinder;
  double radius = 0.0;  ///< [m] cylinder
  double width = 0.0;   ///< [m] prism, along the person's y
  double depth = 0.0;   ///< [m] prism, along the person's x
};

/// The person's links: legs, torso, upper arms, forearms, head. Each volume holds its part of
/// the mesh with a margin of about one sigma of the cell's noisiest sensors' range noise.
std::vector<BodyLink> person_links();

}  // namespace rigdesign::sim
