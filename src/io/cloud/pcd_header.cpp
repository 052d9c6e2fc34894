#include "io/cloud/pcd_header.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "io/cloud/cloud_text.hpp"

namespace rigdesign::io {
namespace {

const std::vector<std::string> kKeywords = {"VERSION", "FIELDS", "SIZE",      "TYPE",   "COUNT",
                                            "WIDTH",   "HEIGHT", "VIEWPOINT", "POINTS", "DATA"};
constexpr const char* kPcdKeywordList =
    "one of VERSION, FIELDS, SIZE, TYPE, COUNT, WIDTH, HEIGHT, VIEWPOINT, POINTS, DATA";

// A header line as written: its keyword's values and where it stands.
struct KeywordLine {
  int line = 0;
  std::vector<std::string> values;
};

// Header lines by keyword, up to and including DATA.
struct RawHeader {
  std::string path;
  std::map<std::string, KeywordLine> lines;
  int data_line = 0;
  std::size_t body_offset = 0;

  bool has(const std::string& keyword) const { return lines.count(keyword) > 0; }
  const KeywordLine& required(const std::string& keyword) const {
    const auto found = lines.find(keyword);
    if (found == lines.end()) {
      throw_header_error(path, data_line, keyword, "the header has no " + keyword + " line",
                         "a " + keyword + " line before DATA");
    }
    return found->second;
  }
};

RawHeader read_keyword_lines(const std::string& path, std::string_view bytes) {
  RawHeader raw{path, {}, 0, 0};
  LineCursor cursor(bytes);
  while (const auto line = cursor.next()) {
    const std::vector<std::string_view> words = split_words(*line);
    if (words.empty() || words[0].front() == '#') continue;
    const std::string keyword(words[0]);
    if (std::find(kKeywords.begin(), kKeywords.end(), keyword) == kKeywords.end()) {
      throw_header_error(path, cursor.line_number(), "header",
                         "unknown keyword " + quote_word(words[0]), kPcdKeywordList);
    }
    if (raw.has(keyword)) {
      throw_header_error(
          path, cursor.line_number(), keyword,
          "given twice (first on line " + std::to_string(raw.lines[keyword].line) + ")",
          "each keyword once");
    }
    KeywordLine& entry = raw.lines[keyword];
    entry.line = cursor.line_number();
    for (std::size_t i = 1; i < words.size(); ++i) entry.values.emplace_back(words[i]);
    if (keyword == "DATA") {
      raw.data_line = cursor.line_number();
      raw.body_offset = cursor.offset();
      return raw;
    }
  }
  throw_header_error(path, std::max(cursor.line_number(), 1), "DATA",
                     "the header ends without a DATA line",
                     "DATA ascii, binary or binary_compressed");
}

// The values of a keyword that takes one value per field, checked against FIELDS' length.
const std::vector<std::string>& per_field(const RawHeader& raw, const KeywordLine& entry,
                                          const std::string& keyword, std::size_t field_count) {
  if (entry.values.size() != field_count) {
    throw_header_error(raw.path, entry.line, keyword,
                       "has " + std::to_string(entry.values.size()) + " values for " +
                           std::to_string(field_count) + " FIELDS",
                       "one value per field, in FIELDS order");
  }
  return entry.values;
}

std::size_t single_count(const RawHeader& raw, const std::string& keyword) {
  const KeywordLine& entry = raw.required(keyword);
  const auto value = entry.values.size() == 1 ? parse_count(entry.values[0]) : std::nullopt;
  if (!value) {
    throw_header_error(raw.path, entry.line, keyword, "is not a single non-negative integer",
                       keyword + " <integer>");
  }
  return *value;
}

bool valid_size_for_type(char type, std::size_t size) {
  if (type == 'F') return size == 4 || size == 8;
  return size == 1 || size == 2 || size == 4 || size == 8;
}

std::vector<PcdField> read_fields(const RawHeader& raw) {
  const KeywordLine& names = raw.required("FIELDS");
  if (names.values.empty()) {
    throw_header_error(raw.path, names.line, "FIELDS", "lists no fields", "FIELDS x y z ...");
  }
  const std::size_t n = names.values.size();
  const KeywordLine& size_line = raw.required("SIZE");
  const KeywordLine& type_line = raw.required("TYPE");
  const auto& sizes = per_field(raw, size_line, "SIZE", n);
  const auto& types = per_field(raw, type_line, "TYPE", n);
  const std::vector<std::string> ones(n, "1");
  const KeywordLine* count_line = raw.has("COUNT") ? &raw.lines.at("COUNT") : nullptr;
  const auto& counts = count_line ? per_field(raw, *count_line, "COUNT", n) : ones;

  std::vector<PcdField> fields(n);
  std::size_t offset = 0;
  for (std::size_t i = 0; i < n; ++i) {
    PcdField& field = fields[i];
    field.name = names.values[i];
    const std::string which = " of field " + quote_word(field.name);
    const auto size = parse_count(sizes[i]);
    if (!size || *size == 0) {
      throw_header_error(raw.path, size_line.line, "SIZE",
                         quote_word(sizes[i]) + which + " is not a size", "1, 2, 4 or 8 bytes");
    }
    if (types[i].size() != 1 || std::string("FIU").find(types[i][0]) == std::string::npos) {
      throw_header_error(raw.path, type_line.line, "TYPE",
                         quote_word(types[i]) + which + " is not a type", "F, I or U");
    }
    if (!valid_size_for_type(types[i][0], *size)) {
      throw_header_error(raw.path, type_line.line, "TYPE",
                         "TYPE " + types[i] + " with SIZE " + sizes[i] + which + " does not exist",
                         "F with SIZE 4 or 8; I or U with SIZE 1, 2, 4 or 8");
    }
    const auto count = parse_count(counts[i]);
    if (!count || *count == 0) {
      throw_header_error(raw.path, count_line ? count_line->line : names.line, "COUNT",
                         quote_word(counts[i]) + which + " is not a positive count",
                         "an integer >= 1");
    }
    field.size = *size;
    field.type = types[i][0];
    field.count = *count;
    field.offset = offset;
    std::size_t bytes = 0;
    if (__builtin_mul_overflow(field.size, field.count, &bytes) ||
        __builtin_add_overflow(offset, bytes, &offset)) {
      throw_header_error(raw.path, count_line ? count_line->line : names.line, "COUNT",
                         "the fields add up to more bytes per point than memory holds",
                         "realistic COUNT values");
    }
  }
  return fields;
}

std::size_t record_size(const std::vector<PcdField>& fields) {
  const PcdField& last = fields.back();
  return last.offset + last.size * last.count;
}

// x, y and z must each appear once as one float; other names may repeat only as PCL's "_"
// padding fields.
std::array<std::size_t, 3> find_xyz(const RawHeader& raw, const std::vector<PcdField>& fields) {
  const KeywordLine& names = raw.lines.at("FIELDS");
  for (std::size_t i = 0; i < fields.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (fields[i].name == fields[j].name && fields[i].name != "_") {
        throw_header_error(raw.path, names.line, "FIELDS",
                           "names field " + quote_word(fields[i].name) + " twice",
                           "distinct field names");
      }
    }
  }
  std::array<std::size_t, 3> xyz{};
  const std::array<const char*, 3> axes = {"x", "y", "z"};
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const auto found = std::find_if(fields.begin(), fields.end(),
                                    [&](const PcdField& f) { return f.name == axes[axis]; });
    if (found == fields.end()) {
      throw_header_error(raw.path, names.line, "FIELDS", std::string("has no field ") + axes[axis],
                         "FIELDS with x, y and z");
    }
    if (found->type != 'F') {
      throw_header_error(raw.path, raw.lines.at("TYPE").line, "TYPE",
                         std::string("field ") + axes[axis] + " has TYPE " + found->type,
                         "F for x, y and z");
    }
    if (found->count != 1) {
      throw_header_error(
          raw.path, raw.lines.at("COUNT").line, "COUNT",
          std::string("field ") + axes[axis] + " has COUNT " + std::to_string(found->count),
          "COUNT 1 for x, y and z");
    }
    xyz[axis] = static_cast<std::size_t>(found - fields.begin());
  }
  return xyz;
}

void read_viewpoint(const RawHeader& raw, PcdHeader& header) {
  if (!raw.has("VIEWPOINT")) return;
  const KeywordLine& entry = raw.lines.at("VIEWPOINT");
  const char* expected =
      "VIEWPOINT tx ty tz qw qx qy qz: seven finite numbers, a non-zero quaternion";
  if (entry.values.size() != kViewpointValues) {
    throw_header_error(raw.path, entry.line, "VIEWPOINT",
                       "has " + std::to_string(entry.values.size()) + " values", expected);
  }
  std::array<float, kViewpointValues> values{};
  for (std::size_t i = 0; i < kViewpointValues; ++i) {
    const auto value = parse_float(entry.values[i]);
    if (!value || !std::isfinite(*value)) {
      throw_header_error(raw.path, entry.line, "VIEWPOINT",
                         quote_word(entry.values[i]) + " is not a finite number", expected);
    }
    values[i] = *value;
  }
  header.origin = model::Point3f(values[0], values[1], values[2]);
  const Eigen::Quaternionf orientation(values[3], values[4], values[5], values[6]);
  if (orientation.norm() == 0.0f) {
    throw_header_error(raw.path, entry.line, "VIEWPOINT", "the quaternion is zero", expected);
  }
  header.orientation = orientation.normalized();
}

PcdEncoding read_encoding(const RawHeader& raw) {
  const KeywordLine& entry = raw.lines.at("DATA");
  const std::string value = entry.values.size() == 1 ? entry.values[0] : std::string();
  if (value == "ascii") return PcdEncoding::ascii;
  if (value == "binary") return PcdEncoding::binary;
  if (value == "binary_compressed") return PcdEncoding::binary_compressed;
  throw_header_error(raw.path, entry.line, "DATA",
                     value.empty() ? "needs one encoding" : "unknown encoding " + quote_word(value),
                     "DATA ascii, binary or binary_compressed");
}

void check_point_count(const RawHeader& raw, const PcdHeader& header) {
  std::size_t cells = 0;
  const bool overflows = __builtin_mul_overflow(header.width, header.height, &cells);
  if (overflows || cells != header.points) {
    throw_header_error(raw.path, raw.lines.at("POINTS").line, "POINTS",
                       "POINTS " + std::to_string(header.points) + " differs from WIDTH " +
                           std::to_string(header.width) + " x HEIGHT " +
                           std::to_string(header.height),
                       "POINTS = WIDTH x HEIGHT");
  }
}

}  // namespace

PcdHeader parse_pcd_header(const std::string& path, std::string_view bytes) {
  const RawHeader raw = read_keyword_lines(path, bytes);
  PcdHeader header;
  header.data_line = raw.data_line;
  header.body_offset = raw.body_offset;
  header.fields = read_fields(raw);
  header.record_size = record_size(header.fields);
  // No point can be longer than the file: each value takes at least one byte (binary) or two
  // (ascii: a digit and a separator). A fuzzed COUNT of 4e9 otherwise made the ascii reader
  // name four billion values.
  std::size_t values = 0;
  for (const PcdField& field : header.fields) values += field.count;
  if (header.record_size > bytes.size() || values > bytes.size()) {
    const KeywordLine& line = raw.has("COUNT") ? raw.lines.at("COUNT") : raw.lines.at("FIELDS");
    throw_header_error(path, line.line, "COUNT",
                       "one point would take " + std::to_string(header.record_size) +
                           " bytes, more than the whole file (" + std::to_string(bytes.size()) +
                           " bytes)",
                       "COUNT values that fit the file");
  }
  header.xyz_fields = find_xyz(raw, header.fields);
  header.width = single_count(raw, "WIDTH");
  header.height = single_count(raw, "HEIGHT");
  header.points = single_count(raw, "POINTS");
  check_point_count(raw, header);
  read_viewpoint(raw, header);
  header.encoding = read_encoding(raw);
  return header;
}

std::string to_string(PcdEncoding encoding) {
  switch (encoding) {
    case PcdEncoding::ascii: return "ascii";
    case PcdEncoding::binary: return "binary";
    case PcdEncoding::binary_compressed: return "binary_compressed";
  }
  return "?";
}

}  // namespace rigdesign::io
