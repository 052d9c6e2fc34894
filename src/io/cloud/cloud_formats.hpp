#pragma once
// The two file formats behind read_cloud and write_cloud, one implementation file each
// (pcd_format.cpp, ply_format.cpp). cloud_io.cpp reads the file and picks the format by
// extension. Private to io.
#include <string>
#include <string_view>

#include "rigdesign/io/cloud/cloud_io.hpp"

namespace rigdesign::io {

/// Parses a whole PCD file held in `bytes`; `path` names it in findings.
model::PointCloud parse_pcd(const std::string& path, std::string_view bytes,
                            CloudReadReport& report);
/// The PCD file's bytes for `cloud`: FIELDS x y z as F 4, HEIGHT 1, DATA ascii or binary.
std::string encode_pcd(const model::PointCloud& cloud, CloudEncoding encoding);

/// Parses a whole PLY file held in `bytes`; `path` names it in findings.
model::PointCloud parse_ply(const std::string& path, std::string_view bytes,
                            CloudReadReport& report);
/// The PLY file's bytes for `cloud`: one vertex element with float x y z.
std::string encode_ply(const model::PointCloud& cloud, CloudEncoding encoding);

}  // namespace rigdesign::io
