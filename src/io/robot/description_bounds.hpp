#pragma once
/// Bounds on what a robot description may state before rigdesign computes with it: sizes
/// that are positive and finite, positions within the +-1e8 m every other input keeps
/// (clouds, logs, scenes), and meshes small enough to rasterise (a cap on triangles, as
/// scene files have). urdfdom accepts a zero scale or a joint at 1e300 m; rigdesign would
/// then report a body of radius 0 or export a frame at 1e+300 m without a word.
#include <cstddef>
#include <cstdint>
#include <string>

#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/source_location.hpp"

namespace rigdesign::io {

/// A description's meshes hold at most this many triangles in all: each is rasterised at
/// every angle of a coverage computation (the bundled robots have under 20,000).
constexpr std::size_t kMaxDescriptionTriangles = 2000000;
/// A collision mesh file is at most this large: read before its triangles can be counted
/// (a binary STL of 1.3 M triangles; collision meshes are usually under 1 MB).
constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t{64} << 20;

/// Throws InputError at `where` naming `field` unless every component of `size` is
/// positive and finite (a box's size, a mesh's scale, a radius and length).
void require_positive_size(const model::Vec3& size, const model::SourceLocation& where,
                           const std::string& field, const std::string& expected);

/// Throws InputError at `where` unless `position` is finite and within +-1e8 m.
void require_position_in_bounds(const model::Vec3& position, const model::SourceLocation& where,
                                const std::string& field);

}  // namespace rigdesign::io
