// Values of xacro expressions: construction, Python's str() and truthiness, and xacro's
// reading of literal text.
#include <cctype>
#include <charconv>
#include <cmath>

#include "rigdesign/io/robot/xacro_expression.hpp"
#include "xml_tree.hpp"

namespace rigdesign::io::xacro {
namespace {

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace

Value Value::of_integer(long long value) {
  Value v;
  v.kind = Kind::integer;
  v.integer = value;
  return v;
}

Value Value::of_real(double value) {
  Value v;
  v.kind = Kind::real;
  v.real = value;
  return v;
}

Value Value::of_text(std::string value) {
  Value v;
  v.kind = Kind::text;
  v.text = std::move(value);
  return v;
}

Value Value::of_boolean(bool value) {
  Value v;
  v.kind = Kind::boolean;
  v.boolean = value;
  return v;
}

double Value::number() const {
  switch (kind) {
    case Kind::integer: return static_cast<double>(integer);
    case Kind::real: return real;
    case Kind::boolean: return boolean ? 1.0 : 0.0;
    case Kind::text: break;
  }
  throw ExpressionError("'" + text + "' is text, not a number", 0);
}

std::string to_text(const Value& value) {
  switch (value.kind) {
    case Value::Kind::integer: return std::to_string(value.integer);
    case Value::Kind::boolean: return value.boolean ? "True" : "False";
    case Value::Kind::text: return value.text;
    case Value::Kind::real: break;
  }
  const double x = value.real;
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  // Python's repr: the shortest text that reads back as the same double; positional
  // between 1e-4 and 1e16, with ".0" on whole numbers, else scientific with two exponent digits.
  char buffer[64];
  const double magnitude = std::abs(x);
  if (magnitude != 0.0 && (magnitude < 1e-4 || magnitude >= 1e16)) {
    const auto result =
        std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::scientific);
    std::string text(buffer, result.ptr);
    const auto e = text.find('e');
    std::string mantissa = text.substr(0, e);
    std::string exponent = text.substr(e + 1);
    const char sign = exponent[0] == '-' ? '-' : '+';
    if (exponent[0] == '-' || exponent[0] == '+') exponent = exponent.substr(1);
    if (exponent.size() < 2) exponent = "0" + exponent;
    return mantissa + "e" + sign + exponent;
  }
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::fixed);
  std::string text(buffer, result.ptr);
  if (text.find('.') == std::string::npos) text += ".0";
  return text;
}

bool truthy(const Value& value) {
  switch (value.kind) {
    case Value::Kind::integer: return value.integer != 0;
    case Value::Kind::real: return value.real != 0.0;
    case Value::Kind::boolean: return value.boolean;
    case Value::Kind::text: return !value.text.empty();
  }
  return false;
}

Value parse_literal(const std::string& text) {
  const std::string t = xml::trimmed(text);
  if (!t.empty()) {
    long long integer = 0;
    const char* begin = t.data();
    const char* end = t.data() + t.size();
    if (*begin == '+') ++begin;
    if (begin != end) {
      const auto [ptr, error] = std::from_chars(begin, end, integer);
      if (error == std::errc() && ptr == end) return Value::of_integer(integer);
    }
    double real = 0.0;
    const auto [ptr, error] = std::from_chars(begin, end, real);
    if (error == std::errc() && ptr == end && begin != end) return Value::of_real(real);
    const std::string word = lower(t);
    if (word == "true") return Value::of_boolean(true);
    if (word == "false") return Value::of_boolean(false);
  }
  return Value::of_text(text);
}

}  // namespace rigdesign::io::xacro
