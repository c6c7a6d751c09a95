#pragma once
// A small expression language for procedural density (paper 3.3, fig. 13) and other
// per-vertex fields. Expressions arrive in share links, so parsing is a bounded, non-evaluating
// recursive descent (Pratt) into a postfix program; evaluation is a loop over that program
// with a value stack: no eval, no host access, no unbounded recursion, no allocation per call.
//
// Syntax (ASCII only, whitespace free):
//   numbers      1  2.5  .5  1e-3
//   operators    + - * / ^ (power, right associative, binds tighter than unary minus:
//                -2^2 = -4), % (floored modulo), unary - + !, comparisons < <= > >= == !=
//                (1 or 0), && || (1 or 0, both sides evaluated), c ? a : b
//   functions    sin cos tan asin acos atan atan2(y,x) sqrt exp log (natural) log10 abs sign
//                floor ceil round pow(a,b) min(a,b,...) max(a,b,...) clamp(x,lo,hi)
//                smoothstep(e0,e1,x) step(edge,x) mix(a,b,t) mod(a,b) if(c,a,b)
//   constants    pi e
//   variables    x y z   world position
//                u v w   position in the bounding box, 0..1 per axis (0.5 on a flat axis),
//                        so expressions do not depend on the model's size or units
//                nx ny nz  unit vertex normal
//                k1 k2   principal curvatures (k1 >= k2; positive where the surface bends
//                        away from its normal, like the outside of a sphere)
//                H K     mean (k1+k2)/2 and Gaussian k1*k2 curvature (world units)
//                curv    (|k1|+|k2|)/2 times the bounding box diagonal: 0 where flat, ~3.5 on
//                        a sphere, larger at tight bends; scale-free
//                border  straight distance to the nearest boundary edge, found over the
//                        surface (border_distance.h), over the bounding box diagonal: 0 on
//                        the border; 1 where there is no border to reach (a closed surface).
//                        Density expressions only
// Limits: at most 4096 characters, 64 levels of nesting, 2000 terms. Every violation is an
// InputError naming the problem and its column (1-based).
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ff {

enum class ExprVar : std::uint8_t { X, Y, Z, U, V, W, NX, NY, NZ, K1, K2, H, K, Curv, Border, Count };
constexpr int kNumExprVars = static_cast<int>(ExprVar::Count);
using ExprInputs = std::array<double, kNumExprVars>;

class Expression {
 public:
  static constexpr size_t kMaxLength = 4096;
  static constexpr int kMaxDepth = 64;
  static constexpr int kMaxTerms = 2000;

  // Parses `text`; throws InputError ("unknown name 'alert' at column 1", ...) when it is not
  // a valid expression or exceeds the limits.
  static Expression parse(std::string_view text);

  // The value for one set of inputs (may be inf or NaN, e.g. log(0): the caller checks).
  double evaluate(const ExprInputs& inputs) const;

  bool uses(ExprVar var) const { return (used_ >> static_cast<int>(var)) & 1u; }
  // k1, k2, H, K or curv: the caller has to estimate curvature.
  bool uses_curvature() const;
  int num_terms() const { return static_cast<int>(program_.size()); }

  // clang-format off
  enum class Op : std::uint8_t {
    Number, Var, Neg, Not, Add, Sub, Mul, Div, Mod, Pow, Lt, Le, Gt, Ge, Eq, Ne, And, Or, Select,
    Sin, Cos, Tan, Asin, Acos, Atan, Atan2, Sqrt, Exp, Log, Log10, Abs, Sign, Floor, Ceil, Round,
    Min, Max, Clamp, Smoothstep, Step, Mix
  };
  // clang-format on

  struct Instr {
    Op op = Op::Number;
    int arg = 0;  // variable index, or the argument count of min / max
    double value = 0.0;
  };

 private:
  friend class ExpressionParser;
  std::vector<Instr> program_;  // postfix
  int max_stack_ = 0;
  std::uint32_t used_ = 0;
};

// Named starting points for the page (fig. 13): each a valid expression with values >= 1.
struct DensityPreset {
  const char* name;
  const char* label;
  const char* expression;
};
// In display order. Two element sizes (a smooth 4:1 step across x), a gradient along x,
// radial (dense at the centre of the plan), by curvature (dense where the surface bends),
// finer at the border (4 on the border, about 2 a twentieth of the diagonal in, 1 inside).
inline constexpr std::array<DensityPreset, 6> kDensityPresets{{
    {"uniform", "Uniform", "1"},
    {"twoSizes", "Two element sizes", "1 + 3 * smoothstep(0.45, 0.55, u)"},
    {"gradient", "Gradient", "1 + 3 * u"},
    {"radial", "Radial", "1 + 3 * exp(-8 * ((u - 0.5)^2 + (v - 0.5)^2))"},
    {"curvature", "By curvature", "1 + 2 * min(curv, 4)"},
    {"border", "Finer at borders", "1 + 3 * exp(-border / 0.05)"},
}};

}  // namespace ff
