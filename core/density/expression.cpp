#include "core/density/expression.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "core/util/angles.h"
#include "core/util/error.h"

namespace ff {

namespace {

using Op = Expression::Op;

struct NameInfo {
  const char* name;
  Op op;
  int min_args;
  int max_args;
};

// Functions: (name, op, arity range). min / max take 2..16 arguments.
constexpr NameInfo kFunctions[] = {
    {"sin", Op::Sin, 1, 1},     {"cos", Op::Cos, 1, 1},     {"tan", Op::Tan, 1, 1},
    {"asin", Op::Asin, 1, 1},   {"acos", Op::Acos, 1, 1},   {"atan", Op::Atan, 1, 1},
    {"atan2", Op::Atan2, 2, 2}, {"sqrt", Op::Sqrt, 1, 1},   {"exp", Op::Exp, 1, 1},
    {"log", Op::Log, 1, 1},     {"log10", Op::Log10, 1, 1}, {"abs", Op::Abs, 1, 1},
    {"sign", Op::Sign, 1, 1},   {"floor", Op::Floor, 1, 1}, {"ceil", Op::Ceil, 1, 1},
    {"round", Op::Round, 1, 1}, {"pow", Op::Pow, 2, 2},     {"min", Op::Min, 2, 16},
    {"max", Op::Max, 2, 16},    {"clamp", Op::Clamp, 3, 3}, {"smoothstep", Op::Smoothstep, 3, 3},
    {"step", Op::Step, 2, 2},   {"mix", Op::Mix, 3, 3},     {"mod", Op::Mod, 2, 2},
    {"if", Op::Select, 3, 3},
};

constexpr const char* kVarNames[kNumExprVars] = {"x",  "y",  "z",  "u",  "v", "w", "nx",
                                                 "ny", "nz", "k1", "k2", "H", "K", "curv", "border"};

bool is_ident_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Binding powers of the infix operators (0 = not infix). Higher binds tighter.
int infix_power(Op op) {
  switch (op) {
    case Op::Or:
      return 2;
    case Op::And:
      return 3;
    case Op::Eq:
    case Op::Ne:
      return 4;
    case Op::Lt:
    case Op::Le:
    case Op::Gt:
    case Op::Ge:
      return 5;
    case Op::Add:
    case Op::Sub:
      return 6;
    case Op::Mul:
    case Op::Div:
    case Op::Mod:
      return 7;
    case Op::Pow:
      return 9;
    default:
      return 0;
  }
}
constexpr int kTernaryPower = 1;
constexpr int kPrefixPower = 8;  // unary minus: below ^ so -2^2 = -(2^2)

enum class Tok { End, Number, Name, Infix, Bang, LParen, RParen, Comma, Question, Colon };

struct Token {
  Tok kind = Tok::End;
  size_t pos = 0;  // 0-based byte offset
  size_t len = 0;
  Op op = Op::Number;  // for Infix
  double number = 0.0;
};

}  // namespace

class ExpressionParser {
 public:
  explicit ExpressionParser(std::string_view text) : text_(text) {}

  Expression run() {
    if (text_.size() > Expression::kMaxLength)
      fail("is too long (" + std::to_string(text_.size()) + " characters; at most " +
           std::to_string(Expression::kMaxLength) + ")");
    for (size_t i = 0; i < text_.size(); ++i) {
      const unsigned char c = static_cast<unsigned char>(text_[i]);
      if (c >= 0x80) fail("has a non-ASCII character at column " + std::to_string(i + 1));
      if (c < 0x20 && c != ' ' && c != '\t' && c != '\n' && c != '\r')
        fail("has a control character at column " + std::to_string(i + 1));
      if (c == 0x7f) fail("has a control character at column " + std::to_string(i + 1));
    }
    next();
    if (tok_.kind == Tok::End) fail("is empty");
    expression(0, 0);
    if (tok_.kind != Tok::End) fail("has unexpected " + describe(tok_) + " at column " + column(tok_));
    out_.max_stack_ = max_stack_;
    return std::move(out_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError("density expression " + what); }
  static std::string column(const Token& t) { return std::to_string(t.pos + 1); }
  std::string describe(const Token& t) const {
    if (t.kind == Tok::End) return "end";
    std::string s(text_.substr(t.pos, std::min<size_t>(t.len, 32)));
    return "'" + s + "'";
  }

  void next() {
    size_t i = pos_;
    while (i < text_.size() && (text_[i] == ' ' || text_[i] == '\t' || text_[i] == '\n' || text_[i] == '\r')) ++i;
    tok_ = Token{};
    tok_.pos = i;
    if (i >= text_.size()) {
      pos_ = i;
      return;
    }
    const char c = text_[i];
    const char d = i + 1 < text_.size() ? text_[i + 1] : '\0';
    size_t len = 1;
    if (is_digit(c) || (c == '.' && is_digit(d))) {
      size_t j = i;
      while (j < text_.size() && is_digit(text_[j])) ++j;
      if (j < text_.size() && text_[j] == '.') ++j;
      while (j < text_.size() && is_digit(text_[j])) ++j;
      if (j < text_.size() && (text_[j] == 'e' || text_[j] == 'E')) {
        size_t k = j + 1;
        if (k < text_.size() && (text_[k] == '+' || text_[k] == '-')) ++k;
        if (k < text_.size() && is_digit(text_[k])) {
          while (k < text_.size() && is_digit(text_[k])) ++k;
          j = k;
        }
      }
      const std::string digits(text_.substr(i, j - i));
      tok_.kind = Tok::Number;
      tok_.number = std::strtod(digits.c_str(), nullptr);
      if (!std::isfinite(tok_.number)) fail("has a number too large at column " + std::to_string(i + 1));
      len = j - i;
    } else if (is_ident_start(c)) {
      size_t j = i;
      while (j < text_.size() && (is_ident_start(text_[j]) || is_digit(text_[j]))) ++j;
      tok_.kind = Tok::Name;
      len = j - i;
    } else {
      tok_.kind = Tok::Infix;
      const auto two = [&](char second, Op op2, Op op1) {
        if (d == second) {
          len = 2;
          tok_.op = op2;
        } else {
          tok_.op = op1;
        }
      };
      switch (c) {
        case '+':
          tok_.op = Op::Add;
          break;
        case '-':
          tok_.op = Op::Sub;
          break;
        case '*':
          tok_.op = Op::Mul;
          break;
        case '/':
          tok_.op = Op::Div;
          break;
        case '%':
          tok_.op = Op::Mod;
          break;
        case '^':
          tok_.op = Op::Pow;
          break;
        case '<':
          two('=', Op::Le, Op::Lt);
          break;
        case '>':
          two('=', Op::Ge, Op::Gt);
          break;
        case '=':
          if (d != '=') fail("has '=' at column " + std::to_string(i + 1) + " (compare with '==')");
          len = 2;
          tok_.op = Op::Eq;
          break;
        case '!':
          if (d == '=') {
            len = 2;
            tok_.op = Op::Ne;
          } else {
            tok_.kind = Tok::Bang;
          }
          break;
        case '&':
          if (d != '&') fail("has '&' at column " + std::to_string(i + 1) + " (use '&&')");
          len = 2;
          tok_.op = Op::And;
          break;
        case '|':
          if (d != '|') fail("has '|' at column " + std::to_string(i + 1) + " (use '||')");
          len = 2;
          tok_.op = Op::Or;
          break;
        case '(':
          tok_.kind = Tok::LParen;
          break;
        case ')':
          tok_.kind = Tok::RParen;
          break;
        case ',':
          tok_.kind = Tok::Comma;
          break;
        case '?':
          tok_.kind = Tok::Question;
          break;
        case ':':
          tok_.kind = Tok::Colon;
          break;
        default:
          fail("has unexpected character '" + std::string(1, c) + "' at column " + std::to_string(i + 1));
      }
    }
    tok_.len = len;
    pos_ = i + len;
  }

  void emit(Op op, int arg = 0, double value = 0.0, int pops = 0) {
    if (static_cast<int>(out_.program_.size()) >= Expression::kMaxTerms)
      fail("has too many terms (more than " + std::to_string(Expression::kMaxTerms) + ")");
    out_.program_.push_back(Expression::Instr{op, arg, value});
    stack_ += 1 - pops;
    max_stack_ = std::max(max_stack_, stack_);
  }

  void expect(Tok kind, const char* what) {
    if (tok_.kind != kind)
      fail("expected " + std::string(what) + " at column " + column(tok_) + ", found " + describe(tok_));
    next();
  }

  // Pratt loop. `depth` counts recursion: checked before recursing any further, so hostile
  // nesting ("((((...", "----...", "2^2^2^...") stops at kMaxDepth, never on the stack.
  void expression(int min_power, int depth) {
    if (depth >= Expression::kMaxDepth)
      fail("is nested too deeply at column " + column(tok_) + " (at most " + std::to_string(Expression::kMaxDepth) +
           " levels)");
    prefix(depth);
    for (;;) {
      if (tok_.kind == Tok::Question) {
        if (kTernaryPower <= min_power) return;
        next();
        expression(0, depth + 1);
        expect(Tok::Colon, "':'");
        expression(kTernaryPower - 1, depth + 1);  // right associative
        emit(Op::Select, 0, 0.0, 3);
        continue;
      }
      if (tok_.kind != Tok::Infix) return;
      const Op op = tok_.op;
      const int power = infix_power(op);
      if (power <= min_power) return;
      next();
      expression(op == Op::Pow ? power - 1 : power, depth + 1);
      emit(op, 0, 0.0, 2);
    }
  }

  void prefix(int depth) {
    const Token t = tok_;
    switch (t.kind) {
      case Tok::Number:
        next();
        emit(Op::Number, 0, t.number);
        return;
      case Tok::LParen:
        next();
        expression(0, depth + 1);
        expect(Tok::RParen, "')'");
        return;
      case Tok::Bang:
        next();
        expression(kPrefixPower, depth + 1);
        emit(Op::Not, 0, 0.0, 1);
        return;
      case Tok::Infix:
        if (t.op == Op::Sub || t.op == Op::Add) {
          next();
          expression(kPrefixPower, depth + 1);
          if (t.op == Op::Sub) emit(Op::Neg, 0, 0.0, 1);
          return;
        }
        break;
      case Tok::Name:
        name(depth);
        return;
      default:
        break;
    }
    if (t.kind == Tok::End) fail("ends early: expected a value at column " + column(t));
    fail("has unexpected " + describe(t) + " at column " + column(t) + " (expected a value)");
  }

  void name(int depth) {
    const Token t = tok_;
    const std::string_view id = text_.substr(t.pos, t.len);
    next();
    const bool call = tok_.kind == Tok::LParen;
    for (const NameInfo& f : kFunctions) {
      if (id != f.name) continue;
      if (!call) fail("has function '" + std::string(id) + "' without '(' at column " + column(t));
      next();
      int args = 0;
      if (tok_.kind != Tok::RParen) {
        for (;;) {
          expression(0, depth + 1);
          ++args;
          if (tok_.kind != Tok::Comma) break;
          next();
        }
      }
      if (args < f.min_args || args > f.max_args) {
        const std::string want = f.min_args == f.max_args
                                     ? std::to_string(f.min_args)
                                     : std::to_string(f.min_args) + " to " + std::to_string(f.max_args);
        fail("calls '" + std::string(id) + "' at column " + column(t) + " with " + std::to_string(args) +
             (args == 1 ? " argument" : " arguments") + " (it takes " + want + ")");
      }
      expect(Tok::RParen, "')'");
      emit(f.op, args, 0.0, args);
      return;
    }
    const auto unknown = [&] {
      fail("has unknown name '" + std::string(id.substr(0, 32)) + (id.size() > 32 ? "..." : "") + "' at column " +
           column(t));
    };
    if (call) {
      for (const char* v : kVarNames)
        if (id == v) fail("calls '" + std::string(id) + "' at column " + column(t) + ", which is not a function");
      unknown();
    }
    if (id == "pi") return emit(Op::Number, 0, kPi);
    if (id == "e") return emit(Op::Number, 0, 2.71828182845904523536);
    for (int v = 0; v < kNumExprVars; ++v) {
      if (id != kVarNames[v]) continue;
      out_.used_ |= 1u << v;
      return emit(Op::Var, v);
    }
    unknown();
  }

  std::string_view text_;
  size_t pos_ = 0;
  Token tok_;
  Expression out_;
  int stack_ = 0;
  int max_stack_ = 0;
};

Expression Expression::parse(std::string_view text) { return ExpressionParser(text).run(); }

bool Expression::uses_curvature() const {
  return uses(ExprVar::K1) || uses(ExprVar::K2) || uses(ExprVar::H) || uses(ExprVar::K) || uses(ExprVar::Curv);
}

}  // namespace ff
