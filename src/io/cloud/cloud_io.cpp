#include "rigdesign/io/cloud/cloud_io.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "io/cloud/cloud_formats.hpp"
#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/io/file_bytes.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {
namespace {

enum class CloudFormat { pcd, ply, unknown };

CloudFormat format_of(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".pcd") return CloudFormat::pcd;
  if (extension == ".ply") return CloudFormat::ply;
  return CloudFormat::unknown;
}

[[noreturn]] void throw_unknown_extension(const std::string& path, const std::string& field) {
  throw model::InputError(model::Diagnostic{
      {path, 0, 0}, field, "is neither a .pcd nor a .ply file", "a path ending in .pcd or .ply"});
}

}  // namespace

model::PointCloud read_cloud(const std::string& path, CloudReadReport* report) {
  const CloudFormat format = format_of(path);
  if (format == CloudFormat::unknown) throw_unknown_extension(path, "file");
  const std::string bytes = io::read_file_bytes(path, "a readable point cloud file");
  CloudReadReport local_report;
  CloudReadReport& filled = report ? *report : local_report;
  filled = CloudReadReport{};
  return format == CloudFormat::pcd ? io::parse_pcd(path, bytes, filled)
                                    : io::parse_ply(path, bytes, filled);
}

void write_cloud(const std::string& path, const model::PointCloud& cloud, CloudEncoding encoding) {
  const CloudFormat format = format_of(path);
  if (format == CloudFormat::unknown) throw_unknown_extension(path, "output");
  write_file_atomically(path, format == CloudFormat::pcd ? io::encode_pcd(cloud, encoding)
                                                         : io::encode_ply(cloud, encoding));
}

}  // namespace rigdesign::io
