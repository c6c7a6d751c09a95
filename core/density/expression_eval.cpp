// The evaluator of expression.h: a loop over the postfix program with a fixed value stack.
#include <algorithm>
#include <array>
#include <cmath>

#include "core/density/expression.h"

namespace ff {

using Op = Expression::Op;

namespace {

double floored_mod(double a, double b) { return a - b * std::floor(a / b); }

double smoothstep(double e0, double e1, double x) {
  if (e0 == e1) return x < e0 ? 0.0 : 1.0;
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

}  // namespace

double Expression::evaluate(const ExprInputs& in) const {
  // Fixed-size value stack: the parser bounds it by kMaxTerms.
  std::array<double, kMaxTerms + 1> stack;
  int top = 0;  // number of values
  const auto b2 = [&](double r) {
    --top;
    stack[static_cast<size_t>(top - 1)] = r;
  };
  for (const Instr& ins : program_) {
    double* s = stack.data() + top;  // s[-1] is the top
    switch (ins.op) {
      case Op::Number:
        stack[static_cast<size_t>(top++)] = ins.value;
        break;
      case Op::Var:
        stack[static_cast<size_t>(top++)] = in[static_cast<size_t>(ins.arg)];
        break;
      case Op::Neg:
        s[-1] = -s[-1];
        break;
      case Op::Not:
        s[-1] = s[-1] == 0.0 ? 1.0 : 0.0;
        break;
      case Op::Add:
        b2(s[-2] + s[-1]);
        break;
      case Op::Sub:
        b2(s[-2] - s[-1]);
        break;
      case Op::Mul:
        b2(s[-2] * s[-1]);
        break;
      case Op::Div:
        b2(s[-2] / s[-1]);
        break;
      case Op::Mod:
        b2(floored_mod(s[-2], s[-1]));
        break;
      case Op::Pow:
        b2(std::pow(s[-2], s[-1]));
        break;
      case Op::Lt:
        b2(s[-2] < s[-1] ? 1.0 : 0.0);
        break;
      case Op::Le:
        b2(s[-2] <= s[-1] ? 1.0 : 0.0);
        break;
      case Op::Gt:
        b2(s[-2] > s[-1] ? 1.0 : 0.0);
        break;
      case Op::Ge:
        b2(s[-2] >= s[-1] ? 1.0 : 0.0);
        break;
      case Op::Eq:
        b2(s[-2] == s[-1] ? 1.0 : 0.0);
        break;
      case Op::Ne:
        b2(s[-2] != s[-1] ? 1.0 : 0.0);
        break;
      case Op::And:
        b2(s[-2] != 0.0 && s[-1] != 0.0 ? 1.0 : 0.0);
        break;
      case Op::Or:
        b2(s[-2] != 0.0 || s[-1] != 0.0 ? 1.0 : 0.0);
        break;
      case Op::Select:
        top -= 2;
        s[-3] = s[-3] != 0.0 ? s[-2] : s[-1];
        break;
      case Op::Sin:
        s[-1] = std::sin(s[-1]);
        break;
      case Op::Cos:
        s[-1] = std::cos(s[-1]);
        break;
      case Op::Tan:
        s[-1] = std::tan(s[-1]);
        break;
      case Op::Asin:
        s[-1] = std::asin(s[-1]);
        break;
      case Op::Acos:
        s[-1] = std::acos(s[-1]);
        break;
      case Op::Atan:
        s[-1] = std::atan(s[-1]);
        break;
      case Op::Atan2:
        b2(std::atan2(s[-2], s[-1]));
        break;
      case Op::Sqrt:
        s[-1] = std::sqrt(s[-1]);
        break;
      case Op::Exp:
        s[-1] = std::exp(s[-1]);
        break;
      case Op::Log:
        s[-1] = std::log(s[-1]);
        break;
      case Op::Log10:
        s[-1] = std::log10(s[-1]);
        break;
      case Op::Abs:
        s[-1] = std::abs(s[-1]);
        break;
      case Op::Sign:
        s[-1] = s[-1] > 0.0 ? 1.0 : (s[-1] < 0.0 ? -1.0 : 0.0);
        break;
      case Op::Floor:
        s[-1] = std::floor(s[-1]);
        break;
      case Op::Ceil:
        s[-1] = std::ceil(s[-1]);
        break;
      case Op::Round:
        s[-1] = std::round(s[-1]);
        break;
      case Op::Min:
      case Op::Max: {
        double r = s[-ins.arg];
        for (int k = ins.arg - 1; k >= 1; --k) r = ins.op == Op::Min ? std::min(r, s[-k]) : std::max(r, s[-k]);
        top -= ins.arg - 1;
        stack[static_cast<size_t>(top - 1)] = r;
        break;
      }
      case Op::Clamp:
        top -= 2;
        s[-3] = std::min(std::max(s[-3], s[-2]), s[-1]);
        break;
      case Op::Smoothstep:
        top -= 2;
        s[-3] = smoothstep(s[-3], s[-2], s[-1]);
        break;
      case Op::Step:
        b2(s[-1] < s[-2] ? 0.0 : 1.0);
        break;
      case Op::Mix:
        top -= 2;
        s[-3] = s[-3] + (s[-2] - s[-3]) * s[-1];
        break;
    }
  }
  return top == 1 ? stack[0] : std::nan("");
}

}  // namespace ff
