#include "io/cloud/ply_header.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <utility>

#include "io/cloud/cloud_text.hpp"

namespace rigdesign::io {
namespace {

constexpr const char* kPlyKeywordList =
    "one of format, comment, obj_info, element, property, end_header";
constexpr const char* kTypeList =
    "char, uchar, short, ushort, int, uint, float, double (or int8 ... float64)";

// Both the original names and the sized aliases later writers use.
const std::vector<std::pair<std::string_view, PlyScalar>> kTypeNames = {
    {"char", PlyScalar::int8},      {"int8", PlyScalar::int8},       {"uchar", PlyScalar::uint8},
    {"uint8", PlyScalar::uint8},    {"short", PlyScalar::int16},     {"int16", PlyScalar::int16},
    {"ushort", PlyScalar::uint16},  {"uint16", PlyScalar::uint16},   {"int", PlyScalar::int32},
    {"int32", PlyScalar::int32},    {"uint", PlyScalar::uint32},     {"uint32", PlyScalar::uint32},
    {"float", PlyScalar::float32},  {"float32", PlyScalar::float32}, {"double", PlyScalar::float64},
    {"float64", PlyScalar::float64}};

std::optional<PlyScalar> scalar_named(std::string_view name) {
  for (const auto& [type_name, type] : kTypeNames) {
    if (type_name == name) return type;
  }
  return std::nullopt;
}

// Reads the header line by line; keeps the state the lines build up.
class HeaderParser {
 public:
  HeaderParser(const std::string& path, std::string_view bytes) : path_(path), cursor_(bytes) {}

  PlyHeader parse() {
    read_magic();
    while (const auto line = cursor_.next()) {
      const std::vector<std::string_view> words = split_words(*line);
      if (words.empty()) continue;
      const std::string_view keyword = words[0];
      if (keyword == "end_header") return finish();
      if (keyword == "format") {
        read_format(words);
      } else if (keyword == "comment") {
        read_comment(words);
      } else if (keyword == "element") {
        read_element(words);
      } else if (keyword == "property") {
        read_property(words);
      } else if (keyword != "obj_info") {
        fail("header", "unknown keyword " + quote_word(keyword), kPlyKeywordList);
      }
    }
    fail("end_header", "the header ends without an end_header line", "end_header");
  }

 private:
  [[noreturn]] void fail(const std::string& field, const std::string& problem,
                         const std::string& expected) const {
    throw_header_error(path_, std::max(cursor_.line_number(), 1), field, problem, expected);
  }

  void read_magic() {
    const auto first = cursor_.next();
    if (!first || *first != "ply") {
      fail("ply", "the file does not start with 'ply'", "'ply' alone on the first line");
    }
  }

  void read_format(const std::vector<std::string_view>& words) {
    const char* expected = "format ascii 1.0 or format binary_little_endian 1.0";
    if (has_format_) fail("format", "given twice", expected);
    if (words.size() != 3) fail("format", "needs an encoding and a version", expected);
    if (words[1] == "ascii") {
      header_.encoding = PlyEncoding::ascii;
    } else if (words[1] == "binary_little_endian") {
      header_.encoding = PlyEncoding::binary_little_endian;
    } else if (words[1] == "binary_big_endian") {
      fail("format", "binary_big_endian is not supported", expected);
    } else {
      fail("format", "unknown encoding " + quote_word(words[1]), expected);
    }
    has_format_ = true;
  }

  // Other comments are free text; only a well-formed viewpoint comment counts.
  void read_comment(const std::vector<std::string_view>& words) {
    if (words.size() != 2 + kViewpointValues || words[1] != "viewpoint") return;
    std::array<float, kViewpointValues> values{};
    for (std::size_t i = 0; i < kViewpointValues; ++i) {
      const auto value = parse_float(words[2 + i]);
      if (!value || !std::isfinite(*value)) return;
      values[i] = *value;
    }
    const Eigen::Quaternionf orientation(values[3], values[4], values[5], values[6]);
    if (orientation.norm() == 0.0f) return;
    header_.origin = model::Point3f(values[0], values[1], values[2]);
    header_.orientation = orientation.normalized();
  }

  void read_element(const std::vector<std::string_view>& words) {
    const auto count = words.size() == 3 ? parse_count(words[2]) : std::nullopt;
    if (!count) fail("element", "is not 'element <name> <count>'", "element <name> <count>");
    header_.elements.push_back({std::string(words[1]), *count, {}, cursor_.line_number()});
  }

  PlyScalar scalar(std::string_view name) const {
    const auto type = scalar_named(name);
    if (!type) fail("property", "unknown type " + quote_word(name), kTypeList);
    return *type;
  }

  void read_property(const std::vector<std::string_view>& words) {
    if (header_.elements.empty()) {
      fail("property", "comes before any element", "property lines after their element line");
    }
    PlyProperty property;
    property.line = cursor_.line_number();
    if (words.size() == 5 && words[1] == "list") {
      property.is_list = true;
      property.list_count_type = scalar(words[2]);
      if (property.list_count_type == PlyScalar::float32 ||
          property.list_count_type == PlyScalar::float64) {
        fail("property", "a list's length must have an integer type", "uchar, ushort or uint");
      }
      property.type = scalar(words[3]);
      property.name = words[4];
    } else if (words.size() == 3) {
      property.type = scalar(words[1]);
      property.name = words[2];
    } else {
      fail("property", "is neither 'property <type> <name>' nor a list",
           "property <type> <name> or property list <count type> <item type> <name>");
    }
    header_.elements.back().properties.push_back(std::move(property));
  }

  PlyHeader finish() {
    header_.end_header_line = cursor_.line_number();
    header_.body_offset = cursor_.offset();
    if (!has_format_) {
      fail("format", "the header has no format line",
           "format ascii 1.0 or format binary_little_endian 1.0");
    }
    const auto vertex = std::find_if(header_.elements.begin(), header_.elements.end(),
                                     [](const PlyElement& e) { return e.name == "vertex"; });
    if (vertex == header_.elements.end()) {
      fail("element vertex", "the header declares no vertex element",
           "element vertex <count> with properties x, y, z");
    }
    header_.vertex_element = static_cast<std::size_t>(vertex - header_.elements.begin());
    check_vertex_properties(*vertex);
    return header_;
  }

  void check_vertex_properties(const PlyElement& vertex) {
    const auto& properties = vertex.properties;
    for (std::size_t i = 0; i < properties.size(); ++i) {
      const PlyProperty& property = properties[i];
      if (property.is_list) {
        throw_header_error(
            path_, property.line, "property",
            "list property " + quote_word(property.name) + " in element vertex is not supported",
            "scalar vertex properties");
      }
      for (std::size_t j = 0; j < i; ++j) {
        if (properties[j].name == property.name) {
          throw_header_error(path_, property.line, "property",
                             "vertex property " + quote_word(property.name) + " is given twice",
                             "distinct property names");
        }
      }
    }
    const std::array<const char*, 3> axes = {"x", "y", "z"};
    for (std::size_t axis = 0; axis < 3; ++axis) {
      const auto found = std::find_if(properties.begin(), properties.end(),
                                      [&](const PlyProperty& p) { return p.name == axes[axis]; });
      if (found == properties.end()) {
        throw_header_error(path_, vertex.line, "element vertex",
                           std::string("has no property ") + axes[axis], "properties x, y and z");
      }
      if (found->type != PlyScalar::float32 && found->type != PlyScalar::float64) {
        throw_header_error(path_, found->line, "property",
                           std::string("vertex property ") + axes[axis] + " is not float or double",
                           "property float " + std::string(axes[axis]) + " (or double)");
      }
      header_.xyz_properties[axis] = static_cast<std::size_t>(found - properties.begin());
    }
  }

  const std::string& path_;
  LineCursor cursor_;
  PlyHeader header_;
  bool has_format_ = false;
};

template <typename Value>
double load(std::string_view bytes, std::size_t at) {
  Value value;
  std::memcpy(&value, bytes.data() + at, sizeof value);
  return static_cast<double>(value);
}

}  // namespace

std::size_t size_of(PlyScalar type) {
  switch (type) {
    case PlyScalar::int8:
    case PlyScalar::uint8: return 1;
    case PlyScalar::int16:
    case PlyScalar::uint16: return 2;
    case PlyScalar::int32:
    case PlyScalar::uint32:
    case PlyScalar::float32: return 4;
    case PlyScalar::float64: return 8;
  }
  return 0;
}

PlyHeader parse_ply_header(const std::string& path, std::string_view bytes) {
  return HeaderParser(path, bytes).parse();
}

std::string to_string(PlyEncoding encoding) {
  return encoding == PlyEncoding::ascii ? "ascii" : "binary_little_endian";
}

double read_ply_scalar(std::string_view bytes, std::size_t at, PlyScalar type) {
  switch (type) {
    case PlyScalar::int8: return load<std::int8_t>(bytes, at);
    case PlyScalar::uint8: return load<std::uint8_t>(bytes, at);
    case PlyScalar::int16: return load<std::int16_t>(bytes, at);
    case PlyScalar::uint16: return load<std::uint16_t>(bytes, at);
    case PlyScalar::int32: return load<std::int32_t>(bytes, at);
    case PlyScalar::uint32: return load<std::uint32_t>(bytes, at);
    case PlyScalar::float32: return load<float>(bytes, at);
    case PlyScalar::float64: return load<double>(bytes, at);
  }
  return 0.0;
}

}  // namespace rigdesign::io
