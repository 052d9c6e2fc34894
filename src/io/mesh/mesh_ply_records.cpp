#include "io/mesh/mesh_ply_records.hpp"

#include <algorithm>

#include "io/mesh/mesh_formats.hpp"

namespace rigdesign::io {
namespace {

std::size_t column(std::string_view line, std::string_view word) {
  return static_cast<std::size_t>(column_of(line, word));
}

void start_record(const PlyElement& element, std::size_t index, std::size_t first_at,
                  PlyRecord& record) {
  record.index = index;
  record.scalars.assign(element.properties.size(), 0.0);
  record.scalar_at.assign(element.properties.size(), first_at);
  record.items.clear();
  record.item_at.clear();
  record.list_at = first_at;
}

}  // namespace

std::string ply_field(const PlyElement& element, std::size_t record, const std::string& property) {
  return element.name + "[" + std::to_string(record) + "]" +
         (property.empty() ? "" : "." + property);
}

AsciiPlyRecords::AsciiPlyRecords(const std::string& path, std::string_view bytes,
                                 const PlyHeader& header)
    : path_(path), cursor_(bytes, header.body_offset, header.end_header_line) {}

void AsciiPlyRecords::read(const PlyElement& element, std::size_t index, std::size_t wanted,
                           PlyRecord& record) {
  const std::string_view line = next_line(element, index);
  split_words(line, words_);
  record.line = cursor_.line_number();
  start_record(element, index, 1, record);
  std::size_t w = 0;
  const auto next_word = [&](const PlyProperty& property) {
    if (w >= words_.size()) {
      fail(record, line.size() + 1, ply_field(element, index, property.name),
           "the line ends before this value", "one line per record with every property");
    }
    return words_[w++];
  };
  for (std::size_t p = 0; p < element.properties.size(); ++p) {
    const PlyProperty& property = element.properties[p];
    if (!property.is_list) {
      const std::string_view text = next_word(property);
      record.scalar_at[p] = column(line, text);
      record.scalars[p] = number(record, line, text, element, property);
      continue;
    }
    const std::string_view length_text = next_word(property);
    std::int64_t length = 0;
    if (!parse_index(length_text, length) || length < 0) {
      fail(record, column(line, length_text), ply_field(element, index, property.name),
           "list length " + quote_word(length_text) + " is not a count", "an integer >= 0");
    }
    if (p == wanted) record.list_at = column(line, length_text);
    for (std::int64_t i = 0; i < length; ++i) {
      const std::string_view text = next_word(property);
      if (p != wanted) {
        number(record, line, text, element, property);
        continue;
      }
      std::int64_t item = 0;
      if (!parse_index(text, item)) {
        fail(record, column(line, text), ply_field(element, index, property.name),
             quote_word(text) + " is not an integer", "vertex indices: integers from 0");
      }
      record.items.push_back(item);
      record.item_at.push_back(column(line, text));
    }
  }
  if (w < words_.size()) {
    fail(record, column(line, words_[w]), ply_field(element, index, ""),
         "has " + std::to_string(words_.size() - w) + " value(s) more than its properties take",
         "one line per record with exactly the header's properties");
  }
}

void AsciiPlyRecords::fail(const PlyRecord& record, std::size_t column, const std::string& field,
                           const std::string& problem, const std::string& expected) const {
  throw_mesh_error(path_, record.line, static_cast<int>(column), field, problem, expected);
}

std::string_view AsciiPlyRecords::next_line(const PlyElement& element, std::size_t index) {
  while (const auto line = cursor_.next()) {
    if (!split_words(*line).empty()) return *line;
  }
  throw_mesh_error(path_, std::max(cursor_.line_number(), 1), 1, ply_field(element, index, ""),
                   "the file ends after " + std::to_string(index) + " of " +
                       std::to_string(element.count) + " " + element.name + " records",
                   "as many records as the header declares");
}

double AsciiPlyRecords::number(const PlyRecord& record, std::string_view line,
                               std::string_view text, const PlyElement& element,
                               const PlyProperty& property) const {
  const auto value = parse_double(text);
  if (!value) {
    fail(record, column(line, text), ply_field(element, record.index, property.name),
         quote_word(text) + " is not a number", "a number");
  }
  return *value;
}

BinaryPlyRecords::BinaryPlyRecords(const std::string& path, std::string_view bytes,
                                   const PlyHeader& header)
    : path_(path), bytes_(bytes), offset_(header.body_offset) {}

void BinaryPlyRecords::read(const PlyElement& element, std::size_t index, std::size_t wanted,
                            PlyRecord& record) {
  record.line = 0;
  start_record(element, index, offset_, record);
  const std::size_t start = offset_;
  for (std::size_t p = 0; p < element.properties.size(); ++p) {
    const PlyProperty& property = element.properties[p];
    if (!property.is_list) {
      need(size_of(property.type), element, index, start);
      record.scalar_at[p] = offset_;
      record.scalars[p] = read_ply_scalar(bytes_, offset_, property.type);
      offset_ += size_of(property.type);
      continue;
    }
    need(size_of(property.list_count_type), element, index, start);
    const double length = read_ply_scalar(bytes_, offset_, property.list_count_type);
    if (length < 0) {
      fail(record, offset_, ply_field(element, index, property.name),
           "negative list length " + std::to_string(static_cast<std::int64_t>(length)),
           "a list length >= 0");
    }
    if (p == wanted) record.list_at = offset_;
    offset_ += size_of(property.list_count_type);
    const std::size_t item_size = size_of(property.type);
    const auto items = static_cast<std::size_t>(length);
    if (items > (bytes_.size() - offset_) / item_size) truncated(element, index, start);
    for (std::size_t i = 0; i < items && p == wanted; ++i) {
      const std::size_t at = offset_ + i * item_size;
      record.items.push_back(static_cast<std::int64_t>(read_ply_scalar(bytes_, at, property.type)));
      record.item_at.push_back(at);
    }
    offset_ += items * item_size;
  }
}

void BinaryPlyRecords::fail(const PlyRecord& record, std::size_t offset, const std::string& field,
                            const std::string& problem, const std::string& expected) const {
  throw_mesh_error(path_, 0, 0, field,
                   problem + " (binary record " + std::to_string(record.index) +
                       " of its element, byte offset " + std::to_string(offset) + ")",
                   expected);
}

void BinaryPlyRecords::need(std::size_t size, const PlyElement& element, std::size_t index,
                            std::size_t start) {
  if (size > bytes_.size() - offset_) truncated(element, index, start);
}

void BinaryPlyRecords::truncated(const PlyElement& element, std::size_t index,
                                 std::size_t start) const {
  throw_mesh_error(
      path_, 0, 0, ply_field(element, index, ""),
      "the binary body ends inside " + element.name + " record " + std::to_string(index) +
          " (it starts at byte offset " + std::to_string(start) + ")",
      std::to_string(element.count) + " " + element.name + " records as the header declares");
}

}  // namespace rigdesign::io
