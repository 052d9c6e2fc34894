#pragma once
/// The expressions inside xacro's ${...}: xacro evaluates them as Python, and robot
/// descriptions use a small part of it: numbers, strings, booleans, names, arithmetic,
/// comparisons, and/or/not, `a if c else b`, and math functions (pi, radians, sin, ...).
/// This is that part, with Python's semantics for it (true division, floor division and
/// modulo, ** binding tighter than unary minus, str() of floats as repr).
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

namespace rigdesign::io::xacro {

/// A value of a xacro expression, with Python's types as xacro uses them.
struct Value {
  enum class Kind { integer, real, text, boolean };
  Kind kind = Kind::integer;
  long long integer = 0;
  double real = 0.0;
  std::string text;
  bool boolean = false;

  static Value of_integer(long long value);
  static Value of_real(double value);
  static Value of_text(std::string value);
  static Value of_boolean(bool value);
  bool is_number() const { return kind != Kind::text; }
  /// integer, real or boolean as a double; throws ExpressionError for text.
  double number() const;
};

class ExpressionError : public std::runtime_error {
 public:
  ExpressionError(const std::string& message, std::size_t offset)
      : std::runtime_error(message), offset_(offset) {}
  /// Where in the expression the problem is (0-based).
  std::size_t offset() const { return offset_; }

 private:
  std::size_t offset_;
};

/// Python's str(): integers as digits, reals as repr (shortest round trip: 0.1, 6.0, 1e-09,
/// inf), booleans True / False, text as is.
std::string to_text(const Value& value);

/// Python's truthiness.
bool truthy(const Value& value);

/// xacro's reading of a property's text: an int if it reads as one, else a float, else
/// true / false (any letter case) as a boolean, else the text itself.
Value parse_literal(const std::string& text);

/// Looks a name up (properties, macro parameters); nothing when it is not defined.
using Lookup = std::function<std::optional<Value>(const std::string& name)>;

/// Evaluates `expression` (the text between ${ and }). Throws ExpressionError (and nothing
/// else of its own) for a syntax error, an undefined name, a type error or a division by
/// zero; exceptions thrown by `lookup` pass through.
Value evaluate(const std::string& expression, const Lookup& lookup);

}  // namespace rigdesign::io::xacro
