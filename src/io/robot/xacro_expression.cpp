// A recursive-descent evaluator for the Python expressions of xacro's ${...}, following
// Python's grammar levels: conditional < or < and < not < comparison < + - < * / // % <
// unary < ** < primary.
#include "rigdesign/io/robot/xacro_expression.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace rigdesign::io::xacro {
namespace {

// Deeper nesting than this is refused rather than risking the stack.
constexpr int kMaxDepth = 200;

bool is_name_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool is_name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

Value integer_or_real(long long a, long long b, char op) {
  long long result = 0;
  bool overflow = false;
  switch (op) {
    case '+': overflow = __builtin_add_overflow(a, b, &result); break;
    case '-': overflow = __builtin_sub_overflow(a, b, &result); break;
    default: overflow = __builtin_mul_overflow(a, b, &result); break;
  }
  if (!overflow) return Value::of_integer(result);
  const double x = static_cast<double>(a);
  const double y = static_cast<double>(b);
  return Value::of_real(op == '+' ? x + y : op == '-' ? x - y : x * y);
}

bool integral(const Value& v) {
  return v.kind == Value::Kind::integer || v.kind == Value::Kind::boolean;
}
long long as_integer(const Value& v) {
  return v.kind == Value::Kind::boolean ? (v.boolean ? 1 : 0) : v.integer;
}

class Parser {
 public:
  Parser(const std::string& text, const Lookup& lookup) : text_(text), lookup_(lookup) {}

  Value run() {
    skip_space();
    if (at_end()) throw ExpressionError("empty expression", 0);
    Value value = conditional();
    skip_space();
    if (!at_end()) throw ExpressionError("unexpected '" + text_.substr(pos_) + "'", pos_);
    return value;
  }

 private:
  bool at_end() const { return pos_ >= text_.size(); }
  void skip_space() {
    while (!at_end() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool accept(const std::string& token) {
    skip_space();
    if (text_.compare(pos_, token.size(), token) != 0) return false;
    pos_ += token.size();
    return true;
  }
  // A keyword only when not followed by a name character ("or" but not "order").
  bool accept_word(const std::string& word) {
    skip_space();
    if (text_.compare(pos_, word.size(), word) != 0) return false;
    const std::size_t after = pos_ + word.size();
    if (after < text_.size() && is_name_char(text_[after])) return false;
    pos_ = after;
    return true;
  }
  void expect(const std::string& token) {
    if (!accept(token)) {
      throw ExpressionError("expected '" + token + "'" +
                                (at_end() ? " at the end" : " before '" + text_.substr(pos_) + "'"),
                            pos_);
    }
  }

  struct DepthGuard {
    explicit DepthGuard(Parser& p) : parser(p) {
      if (++parser.depth_ > kMaxDepth) {
        throw ExpressionError("expression nested too deeply", parser.pos_);
      }
    }
    ~DepthGuard() { --parser.depth_; }
    DepthGuard(const DepthGuard&) = delete;
    DepthGuard& operator=(const DepthGuard&) = delete;
    Parser& parser;
  };

  Value conditional() {
    DepthGuard guard(*this);
    Value value = disjunction();
    if (accept_word("if")) {
      const Value condition = disjunction();
      if (!accept_word("else")) throw ExpressionError("'if' without 'else'", pos_);
      Value otherwise = conditional();
      return truthy(condition) ? value : otherwise;
    }
    return value;
  }

  Value disjunction() {
    Value value = conjunction();
    while (accept_word("or")) {
      Value right = conjunction();
      if (!truthy(value)) value = right;
    }
    return value;
  }

  Value conjunction() {
    Value value = negation();
    while (accept_word("and")) {
      Value right = negation();
      if (truthy(value)) value = right;
    }
    return value;
  }

  Value negation() {
    if (accept_word("not")) {
      DepthGuard guard(*this);
      return Value::of_boolean(!truthy(negation()));
    }
    return comparison();
  }

  Value comparison() {
    Value left = sum();
    bool result = true;
    bool compared = false;
    for (;;) {
      std::string op;
      for (const char* candidate : {"==", "!=", "<=", ">=", "<", ">"}) {
        if (accept(candidate)) {
          op = candidate;
          break;
        }
      }
      if (op.empty()) break;
      const std::size_t at = pos_;
      Value right = sum();
      result = result && compare(left, right, op, at);
      compared = true;
      left = right;
    }
    return compared ? Value::of_boolean(result) : left;
  }

  // `op` applied to two values of one ordered type.
  template <typename T>
  static bool holds(const T& x, const T& y, const std::string& op) {
    if (op == "==") return x == y;
    if (op == "!=") return x != y;
    if (op == "<") return x < y;
    if (op == ">") return x > y;
    if (op == "<=") return x <= y;
    return x >= y;
  }

  static bool compare(const Value& a, const Value& b, const std::string& op, std::size_t at) {
    if (a.kind == Value::Kind::text || b.kind == Value::Kind::text) {
      if (a.kind == b.kind) return holds(a.text, b.text, op);
      if (op == "==") return false;
      if (op == "!=") return true;
      throw ExpressionError("cannot order text and a number with '" + op + "'", at);
    }
    if (integral(a) && integral(b)) return holds(as_integer(a), as_integer(b), op);
    return holds(a.number(), b.number(), op);
  }

  Value sum() {
    Value value = product();
    for (;;) {
      skip_space();
      const std::size_t at = pos_;
      if (accept("+")) {
        const Value right = product();
        if (value.kind == Value::Kind::text && right.kind == Value::Kind::text) {
          value = Value::of_text(value.text + right.text);
        } else {
          value = arithmetic(value, right, '+', at);
        }
      } else if (accept("-")) {
        value = arithmetic(value, product(), '-', at);
      } else {
        return value;
      }
    }
  }

  Value product() {
    Value value = unary();
    for (;;) {
      skip_space();
      const std::size_t at = pos_;
      if (accept("//")) {
        value = arithmetic(value, unary(), 'f', at);
      } else if (accept("*")) {
        value = arithmetic(value, unary(), '*', at);
      } else if (accept("/")) {
        value = arithmetic(value, unary(), '/', at);
      } else if (accept("%")) {
        value = arithmetic(value, unary(), '%', at);
      } else {
        return value;
      }
    }
  }

  static Value arithmetic(const Value& a, const Value& b, char op, std::size_t at) {
    if (a.kind == Value::Kind::text || b.kind == Value::Kind::text) {
      throw ExpressionError(
          std::string("'") + (op == 'f' ? "//" : std::string(1, op)) + "' needs numbers, got text",
          at);
    }
    const bool ints = integral(a) && integral(b);
    if (op == '+' || op == '-' || (op == '*' && ints)) {
      if (ints) return integer_or_real(as_integer(a), as_integer(b), op);
      const double x = a.number();
      const double y = b.number();
      return Value::of_real(op == '+' ? x + y : x - y);
    }
    if (op == '*') return Value::of_real(a.number() * b.number());
    if (b.number() == 0.0) throw ExpressionError("division by zero", at);
    if (op == '/') return Value::of_real(a.number() / b.number());
    if (ints) {
      const long long x = as_integer(a);
      const long long y = as_integer(b);
      if (x == std::numeric_limits<long long>::min() && y == -1) {
        return Value::of_real(-static_cast<double>(x));
      }
      long long q = x / y;
      long long r = x % y;
      if (r != 0 && ((r < 0) != (y < 0))) {  // Python floors toward minus infinity
        --q;
        r += y;
      }
      return Value::of_integer(op == 'f' ? q : r);
    }
    const double x = a.number();
    const double y = b.number();
    const double floored = std::floor(x / y);
    if (op == 'f') return Value::of_real(floored);
    double r = std::fmod(x, y);
    if (r != 0 && ((r < 0) != (y < 0))) r += y;
    return Value::of_real(r);
  }

  Value unary() {
    skip_space();
    if (accept("-")) {
      DepthGuard guard(*this);
      const Value v = unary();
      if (v.kind == Value::Kind::text) throw ExpressionError("'-' needs a number, got text", pos_);
      if (integral(v)) return integer_or_real(0, as_integer(v), '-');
      return Value::of_real(-v.real);
    }
    if (accept("+")) {
      DepthGuard guard(*this);
      const Value v = unary();
      if (v.kind == Value::Kind::text) throw ExpressionError("'+' needs a number, got text", pos_);
      return v.kind == Value::Kind::boolean ? Value::of_integer(as_integer(v)) : v;
    }
    return power();
  }

  Value power() {
    Value base = primary();
    skip_space();
    const std::size_t at = pos_;
    if (!accept("**")) return base;
    DepthGuard guard(*this);
    const Value exponent = unary();  // right-associative, and -2**2 == -(2**2)
    if (base.kind == Value::Kind::text || exponent.kind == Value::Kind::text) {
      throw ExpressionError("'**' needs numbers, got text", at);
    }
    if (integral(base) && integral(exponent) && as_integer(exponent) >= 0) {
      const double result = std::pow(base.number(), exponent.number());
      if (std::abs(result) < 9.0e18)
        return Value::of_integer(static_cast<long long>(std::llround(result)));
      return Value::of_real(result);
    }
    if (base.number() == 0.0 && exponent.number() < 0) {
      throw ExpressionError("0 cannot be raised to a negative power", at);
    }
    return Value::of_real(std::pow(base.number(), exponent.number()));
  }

  Value primary() {
    skip_space();
    if (at_end()) throw ExpressionError("unexpected end of the expression", pos_);
    const char c = text_[pos_];
    if (c == '(') {
      DepthGuard guard(*this);
      ++pos_;
      Value inner = conditional();
      expect(")");
      return inner;
    }
    if (c == '\'' || c == '"') return string_literal(c);
    if (std::isdigit(static_cast<unsigned char>(c)) ||
        (c == '.' && pos_ + 1 < text_.size() &&
         std::isdigit(static_cast<unsigned char>(text_[pos_ + 1])))) {
      return number_literal();
    }
    if (is_name_start(c)) return name_or_call();
    throw ExpressionError("unexpected '" + text_.substr(pos_) + "'", pos_);
  }

  Value string_literal(char quote) {
    const std::size_t start = pos_++;
    std::string value;
    while (!at_end() && text_[pos_] != quote) {
      if (text_[pos_] == '\\' && pos_ + 1 < text_.size()) ++pos_;
      value += text_[pos_++];
    }
    if (at_end()) throw ExpressionError("a string that is never closed", start);
    ++pos_;
    return Value::of_text(value);
  }

  Value number_literal() {
    const std::size_t start = pos_;
    bool real = false;
    while (!at_end() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    if (!at_end() && text_[pos_] == '.') {
      real = true;
      ++pos_;
      while (!at_end() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    }
    if (!at_end() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      std::size_t p = pos_ + 1;
      if (p < text_.size() && (text_[p] == '+' || text_[p] == '-')) ++p;
      if (p < text_.size() && std::isdigit(static_cast<unsigned char>(text_[p]))) {
        real = true;
        pos_ = p;
        while (!at_end() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
      }
    }
    const std::string literal = text_.substr(start, pos_ - start);
    if (!real) {
      long long value = 0;
      const auto [ptr, error] =
          std::from_chars(literal.data(), literal.data() + literal.size(), value);
      if (error == std::errc()) return Value::of_integer(value);
    }
    double value = 0.0;
    std::from_chars(literal.data(), literal.data() + literal.size(), value);
    return Value::of_real(value);
  }

  Value name_or_call() {
    const std::size_t start = pos_;
    while (!at_end() && is_name_char(text_[pos_])) ++pos_;
    const std::string name = text_.substr(start, pos_ - start);
    skip_space();
    if (!at_end() && text_[pos_] == '(') {
      DepthGuard guard(*this);
      ++pos_;
      std::vector<Value> args;
      skip_space();
      if (!accept(")")) {
        do {
          args.push_back(conditional());
        } while (accept(","));
        expect(")");
      }
      return call(name, args, start);
    }
    if (const auto value = lookup_(name)) return *value;
    if (name == "pi") return Value::of_real(std::numbers::pi);
    if (name == "e") return Value::of_real(std::numbers::e);
    if (name == "inf") return Value::of_real(std::numeric_limits<double>::infinity());
    if (name == "nan") return Value::of_real(std::numeric_limits<double>::quiet_NaN());
    if (name == "True") return Value::of_boolean(true);
    if (name == "False") return Value::of_boolean(false);
    throw ExpressionError("name '" + name + "' is not defined", start);
  }

  static Value call(const std::string& name, const std::vector<Value>& args, std::size_t at) {
    const auto need = [&](std::size_t low, std::size_t high) {
      if (args.size() < low || args.size() > high) {
        throw ExpressionError(
            name + "() takes " +
                (low == high ? std::to_string(low)
                             : std::to_string(low) + " to " + std::to_string(high)) +
                " argument(s), got " + std::to_string(args.size()),
            at);
      }
    };
    const auto x = [&](std::size_t i) {
      if (args[i].kind == Value::Kind::text) {
        throw ExpressionError(name + "() needs a number, got '" + args[i].text + "'", at);
      }
      return args[i].number();
    };
    using Unary = double (*)(double);
    static const std::pair<const char*, Unary> kMath[] = {
        {"sin", [](double v) { return std::sin(v); }},
        {"cos", [](double v) { return std::cos(v); }},
        {"tan", [](double v) { return std::tan(v); }},
        {"asin", [](double v) { return std::asin(v); }},
        {"acos", [](double v) { return std::acos(v); }},
        {"atan", [](double v) { return std::atan(v); }},
        {"sqrt", [](double v) { return std::sqrt(v); }},
        {"exp", [](double v) { return std::exp(v); }},
        {"log10", [](double v) { return std::log10(v); }},
        {"fabs", [](double v) { return std::fabs(v); }},
        {"radians", [](double v) { return v * std::numbers::pi / 180.0; }},
        {"degrees", [](double v) { return v * 180.0 / std::numbers::pi; }}};
    for (const auto& [function, apply] : kMath) {
      if (name == function) {
        need(1, 1);
        return Value::of_real(apply(x(0)));
      }
    }
    if (name == "atan2" || name == "pow") {
      need(2, 2);
      return Value::of_real(name == "pow" ? std::pow(x(0), x(1)) : std::atan2(x(0), x(1)));
    }
    if (name == "log") {
      need(1, 2);
      return Value::of_real(args.size() == 1 ? std::log(x(0)) : std::log(x(0)) / std::log(x(1)));
    }
    if (name == "floor" || name == "ceil" || name == "int" || name == "round") {
      need(1, name == "round" ? 2 : 1);
      if (name == "int" && args[0].kind == Value::Kind::text) {
        const Value literal = parse_literal(args[0].text);
        if (literal.kind != Value::Kind::integer) {
          throw ExpressionError("int() cannot read '" + args[0].text + "'", at);
        }
        return literal;
      }
      const double v = x(0);
      if (name == "round" && args.size() == 2) {
        const double scale = std::pow(10.0, x(1));
        return Value::of_real(std::nearbyint(v * scale) / scale);
      }
      const double r = name == "floor"  ? std::floor(v)
                       : name == "ceil" ? std::ceil(v)
                       : name == "int"  ? std::trunc(v)
                                        : std::nearbyint(v);  // banker's rounding, as Python's
      if (!std::isfinite(r) || std::abs(r) >= 9.0e18) {
        throw ExpressionError(name + "() of " + to_text(args[0]) + " is not an integer", at);
      }
      return Value::of_integer(static_cast<long long>(r));
    }
    if (name == "abs") {
      need(1, 1);
      if (integral(args[0]))
        return integer_or_real(
            0, as_integer(args[0]) < 0 ? -as_integer(args[0]) : as_integer(args[0]), '+');
      return Value::of_real(std::abs(x(0)));
    }
    if (name == "min" || name == "max") {
      need(1, 64);
      Value best = args[0];
      for (std::size_t i = 1; i < args.size(); ++i) {
        const bool less = compare(args[i], best, "<", at);
        if (name == "min" ? less : compare(args[i], best, ">", at)) best = args[i];
      }
      return best;
    }
    if (name == "float") {
      need(1, 1);
      if (args[0].kind == Value::Kind::text) {
        const Value literal = parse_literal(args[0].text);
        if (!literal.is_number() || literal.kind == Value::Kind::boolean) {
          throw ExpressionError("float() cannot read '" + args[0].text + "'", at);
        }
        return Value::of_real(literal.number());
      }
      return Value::of_real(x(0));
    }
    if (name == "str") {
      need(1, 1);
      return Value::of_text(to_text(args[0]));
    }
    if (name == "bool") {
      need(1, 1);
      return Value::of_boolean(truthy(args[0]));
    }
    if (name == "len") {
      need(1, 1);
      if (args[0].kind != Value::Kind::text) throw ExpressionError("len() needs text", at);
      return Value::of_integer(static_cast<long long>(args[0].text.size()));
    }
    throw ExpressionError("function '" + name + "' is not defined", at);
  }

  const std::string& text_;
  const Lookup& lookup_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

}  // namespace

Value evaluate(const std::string& expression, const Lookup& lookup) {
  return Parser(expression, lookup).run();
}

}  // namespace rigdesign::io::xacro
