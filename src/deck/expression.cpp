#include "deck/expression.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include "deck/number.hpp"

namespace crumple::deck {

namespace {

bool isNameChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// Recursive descent over the grammar
//   sum     = product { (+|-) product }
//   product = unary { (*|/) unary }
//   unary   = (+|-) unary | power
//   power   = primary [ ** unary ]
//   primary = number | name | name ( sum {, sum} ) | ( sum )
class Parser {
 public:
  Parser(std::string_view text, const ParameterLookup& lookup) : s_(text), lookup_(lookup) {}

  double parse() {
    const double v = sum();
    skipBlanks();
    if (pos_ != s_.size()) fail("unexpected '" + std::string(1, s_[pos_]) + "'");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw ExpressionError("expression '" + std::string(trim(s_)) + "': " + what);
  }
  void skipBlanks() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t')) ++pos_;
  }
  bool accept(std::string_view token) {
    skipBlanks();
    if (s_.substr(pos_, token.size()) != token) return false;
    pos_ += token.size();
    return true;
  }
  void expect(char c) {
    if (!accept(std::string_view(&c, 1))) fail(std::string("expected '") + c + "'");
  }

  double sum() {
    double v = product();
    for (;;) {
      if (accept("+")) {
        v += product();
      } else if (accept("-")) {
        v -= product();
      } else {
        return v;
      }
    }
  }
  double product() {
    double v = unary();
    for (;;) {
      if (accept("*")) {
        v *= unary();
      } else if (accept("/")) {
        const double d = unary();
        if (d == 0.0) fail("division by zero");
        v /= d;
      } else {
        return v;
      }
    }
  }
  double unary() {
    if (accept("-")) return -unary();
    if (accept("+")) return unary();
    return power();
  }
  double power() {
    const double base = primary();
    if (accept("**") || accept("^")) return std::pow(base, unary());
    return base;
  }
  double primary() {
    skipBlanks();
    if (pos_ >= s_.size()) fail("ends too early");
    if (accept("(")) {
      const double v = sum();
      expect(')');
      return v;
    }
    const char c = s_[pos_];
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    accept("&");
    const std::size_t start = pos_;
    while (pos_ < s_.size() && isNameChar(s_[pos_])) ++pos_;
    if (start == pos_) fail("unexpected '" + std::string(1, c) + "'");
    const std::string_view name = s_.substr(start, pos_ - start);
    if (accept("(")) return call(name);
    if (auto v = lookup_(name)) return *v;
    fail("parameter '" + std::string(name) + "' is not defined");
  }
  double number() {
    const std::size_t start = pos_;
    while (pos_ < s_.size() &&
           (std::isdigit(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '.'))
      ++pos_;
    if (pos_ < s_.size() && std::string_view("eEdD").find(s_[pos_]) != std::string_view::npos) {
      std::size_t p = pos_ + 1;
      if (p < s_.size() && (s_[p] == '+' || s_[p] == '-')) ++p;
      if (p < s_.size() && std::isdigit(static_cast<unsigned char>(s_[p]))) {
        pos_ = p;
        while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) ++pos_;
      }
    }
    const auto v = parseReal(s_.substr(start, pos_ - start));
    if (!v) fail("'" + std::string(s_.substr(start, pos_ - start)) + "' is not a number");
    return *v;
  }
  double call(std::string_view name) {
    std::vector<double> args;
    if (!accept(")")) {
      do {
        args.push_back(sum());
      } while (accept(","));
      expect(')');
    }
    std::string f(name);
    std::transform(f.begin(), f.end(), f.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    auto arity = [&](std::size_t n) {
      if (args.size() != n)
        fail(f + "() takes " + std::to_string(n) + " argument" + (n == 1 ? "" : "s"));
    };
    if (f == "min" || f == "max") {
      if (args.empty()) fail(f + "() needs at least one argument");
      return f == "min" ? *std::min_element(args.begin(), args.end())
                        : *std::max_element(args.begin(), args.end());
    }
    if (f == "atan2" || f == "mod" || f == "sign") {
      arity(2);
      if (f == "atan2") return std::atan2(args[0], args[1]);
      if (f == "mod") return std::fmod(args[0], args[1]);
      return std::copysign(std::fabs(args[0]), args[1]);
    }
    arity(1);
    const double x = args[0];
    if (f == "sin") return std::sin(x);
    if (f == "cos") return std::cos(x);
    if (f == "tan") return std::tan(x);
    if (f == "asin") return std::asin(x);
    if (f == "acos") return std::acos(x);
    if (f == "atan") return std::atan(x);
    if (f == "sinh") return std::sinh(x);
    if (f == "cosh") return std::cosh(x);
    if (f == "tanh") return std::tanh(x);
    if (f == "sqrt") {
      if (x < 0) fail("sqrt of a negative number");
      return std::sqrt(x);
    }
    if (f == "exp") return std::exp(x);
    if (f == "log" || f == "log10") {
      if (x <= 0) fail(f + " of a number that is not positive");
      return f == "log" ? std::log(x) : std::log10(x);
    }
    if (f == "abs") return std::fabs(x);
    if (f == "int") return std::trunc(x);
    if (f == "nint") return std::round(x);
    fail("unknown function '" + std::string(name) + "'");
  }

  std::string_view s_;
  const ParameterLookup& lookup_;
  std::size_t pos_ = 0;
};

}  // namespace

double evaluateExpression(std::string_view text, const ParameterLookup& lookup) {
  const double v = Parser(text, lookup).parse();
  if (!std::isfinite(v))
    throw ExpressionError("expression '" + std::string(trim(text)) +
                          "' does not evaluate to a finite number");
  return v;
}

}  // namespace crumple::deck
