#pragma once
// The records of a PLY body, one at a time, for the mesh reader: ascii (one record per
// line, blank lines skipped) and binary_little_endian (records back to back). Both read
// every property of an element so they can walk past the ones the mesh does not keep, and
// both throw located InputErrors. Private to io.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "io/cloud/cloud_text.hpp"
#include "io/cloud/ply_header.hpp"

namespace rigdesign::io {

/// `wanted` value meaning "keep no list's items".
constexpr std::size_t kNoPlyList = std::numeric_limits<std::size_t>::max();

/// One record: every scalar property's value (lists leave 0) and the items of the one list
/// the caller wants, with where each sits: columns on `line` (ascii) or byte offsets (binary).
struct PlyRecord {
  std::size_t index = 0;  ///< record number within its element
  int line = 0;           ///< ascii only
  std::vector<double> scalars;
  std::vector<std::size_t> scalar_at;
  std::vector<std::int64_t> items;
  std::vector<std::size_t> item_at;
  std::size_t list_at = 0;  ///< where the wanted list's length sits
};

/// "face[3].vertex_indices" (or "face[3]" for an empty `property`).
std::string ply_field(const PlyElement& element, std::size_t record, const std::string& property);

class AsciiPlyRecords {
 public:
  AsciiPlyRecords(const std::string& path, std::string_view bytes, const PlyHeader& header);
  /// Reads record `index` of `element` into `record`, keeping the items of the list property
  /// numbered `wanted` (or none). Every word must be a number, the wanted items integers.
  void read(const PlyElement& element, std::size_t index, std::size_t wanted, PlyRecord& record);
  /// Throws InputError at `column` of the record's line.
  [[noreturn]] void fail(const PlyRecord& record, std::size_t column, const std::string& field,
                         const std::string& problem, const std::string& expected) const;

 private:
  std::string_view next_line(const PlyElement& element, std::size_t index);
  double number(const PlyRecord& record, std::string_view line, std::string_view text,
                const PlyElement& element, const PlyProperty& property) const;

  const std::string& path_;
  LineCursor cursor_;
  std::vector<std::string_view> words_;
};

class BinaryPlyRecords {
 public:
  BinaryPlyRecords(const std::string& path, std::string_view bytes, const PlyHeader& header);
  /// As AsciiPlyRecords::read, from the bytes after the previous record.
  void read(const PlyElement& element, std::size_t index, std::size_t wanted, PlyRecord& record);
  /// Throws InputError whose problem names the record and the byte `offset`.
  [[noreturn]] void fail(const PlyRecord& record, std::size_t offset, const std::string& field,
                         const std::string& problem, const std::string& expected) const;

 private:
  void need(std::size_t size, const PlyElement& element, std::size_t index, std::size_t start);
  [[noreturn]] void truncated(const PlyElement& element, std::size_t index,
                              std::size_t start) const;

  const std::string& path_;
  std::string_view bytes_;
  std::size_t offset_;
};

}  // namespace rigdesign::io
