#include "core/remesh_params_json.h"

#include <cmath>
#include <string>

#include "core/density/direction_expression.h"
#include "core/density/expression.h"
#include "core/util/error.h"
#include "core/util/json_reader.h"

namespace ff {

namespace {

constexpr double kMaxCount = 10'000'000;       // panels
constexpr double kMaxIterations = RemeshParams::kMaxIterations;  // k1, k2
constexpr double kMaxWeight = 1e6;

double number(const JsonValue& v, const std::string& name, double lo, double hi, bool integer) {
  if (v.type != JsonValue::Type::Number) throw InputError("parameter '" + name + "' must be a number");
  const double x = v.number;
  if (!std::isfinite(x) || x < lo || x > hi) {
    throw InputError("parameter '" + name + "' must be between " + std::to_string(static_cast<long long>(lo)) +
                     " and " + std::to_string(static_cast<long long>(hi)));
  }
  if (integer && x != std::floor(x)) throw InputError("parameter '" + name + "' must be a whole number");
  return x;
}

bool boolean(const JsonValue& v, const std::string& name) {
  if (v.type != JsonValue::Type::Boolean) throw InputError("parameter '" + name + "' must be true or false");
  return v.boolean;
}

void read_weights(const JsonValue& w, MetricWeights& weights) {
  if (w.type != JsonValue::Type::Object) throw InputError("parameter 'weights' must be an object");
  for (const auto& [name, value] : w.object) {
    const std::string full = "weights." + name;
    if (name == "euclidean")
      weights.euclidean = number(value, full, 0, kMaxWeight, false);
    else if (name == "l2")
      weights.l2 = number(value, full, 0, kMaxWeight, false);
    else if (name == "l21")
      weights.l21 = number(value, full, 0, kMaxWeight, false);
    else if (name == "density")
      weights.density = number(value, full, 0, 8, false);
    else if (name == "boundary")
      weights.boundary = number(value, full, 0, kMaxWeight, false);
    else
      throw InputError("unknown parameter '" + full + "'");
  }
  if (weights.euclidean + weights.l2 + weights.l21 <= 0.0)
    throw InputError("parameter 'weights': at least one of euclidean, l2, l21 must be positive");
}

// The `edits` array (remesh_params_json.h): strict, by name.
std::vector<PanelEdit> read_edits(const JsonValue& v) {
  if (v.type != JsonValue::Type::Array) throw InputError("parameter 'edits' must be an array");
  if (v.array.size() > static_cast<size_t>(kMaxEdits))
    throw InputError("parameter 'edits': at most " + std::to_string(kMaxEdits) + " edits");
  std::vector<PanelEdit> out;
  for (size_t i = 0; i < v.array.size(); ++i) {
    const JsonValue& e = v.array[i];
    const std::string at = "edits[" + std::to_string(i) + "]";
    if (e.type != JsonValue::Type::Object) throw InputError("parameter '" + at + "' must be an object");
    const JsonValue* op = e.find("op");
    if (!op || op->type != JsonValue::Type::String)
      throw InputError("parameter '" + at + ".op' must be \"split\", \"merge\", \"lock\" or \"unlock\"");
    PanelEdit edit;
    if (op->string == "split")
      edit.op = PanelEdit::Op::Split;
    else if (op->string == "merge")
      edit.op = PanelEdit::Op::Merge;
    else if (op->string == "lock")
      edit.op = PanelEdit::Op::Lock;
    else if (op->string == "unlock")
      edit.op = PanelEdit::Op::Unlock;
    else
      throw InputError("parameter '" + at + ".op' must be \"split\", \"merge\", \"lock\" or \"unlock\"");
    const bool merge = edit.op == PanelEdit::Op::Merge;
    bool has_face = false, has_with = false;
    for (const auto& [name, value] : e.object) {
      if (name == "op") continue;
      if (name == "face") {
        edit.face = static_cast<int>(number(value, at + ".face", 0, 2147483647, true));
        has_face = true;
      } else if (name == "with" && merge) {
        edit.with = static_cast<int>(number(value, at + ".with", 0, 2147483647, true));
        has_with = true;
      } else {
        throw InputError("unknown parameter '" + at + "." + name + "'");
      }
    }
    if (!has_face) throw InputError("parameter '" + at + ".face' is missing");
    if (merge && !has_with) throw InputError("parameter '" + at + ".with' is missing (the face on the other panel)");
    out.push_back(edit);
  }
  return out;
}

// {"direction": "none"|"x"|"y"|"z"|"maxCurvature"|"minCurvature"|"expression", "stretch":
// 1..10, "expression": "ex, ey, ez" (direction "expression" only)}; fields left out keep
// their values in `a`.
void read_anisotropy(const JsonValue& v, Anisotropy& a) {
  if (v.type != JsonValue::Type::Object) throw InputError("parameter 'anisotropy' must be an object");
  bool has_expression = false;
  std::string expression;
  for (const auto& [name, value] : v.object) {
    if (name == "direction") {
      if (value.type != JsonValue::Type::String || !set_anisotropy_direction(a, value.string)) {
        throw InputError(
            "parameter 'anisotropy.direction' must be \"none\", \"x\", \"y\", \"z\", \"maxCurvature\", "
            "\"minCurvature\" or \"expression\"");
      }
    } else if (name == "expression") {
      if (value.type != JsonValue::Type::String) throw InputError("parameter 'anisotropy.expression' must be a string");
      has_expression = true;
      expression = value.string;
    } else if (name == "stretch") {
      a.stretch = number(value, "anisotropy.stretch", 1, Anisotropy::kMaxStretch, false);
    } else {
      throw InputError("unknown parameter 'anisotropy." + name + "'");
    }
  }
  const bool procedural = a.direction == AnisotropyDirection::Expression;
  if (has_expression && !procedural)
    throw InputError("parameter 'anisotropy.expression' is only for direction \"expression\"");
  if (has_expression) {
    // Checked here (length, syntax, names) so a bad link fails with its own message.
    try {
      parse_direction_expression(expression);
    } catch (const InputError& e) {
      throw InputError("parameter 'anisotropy.expression': " + std::string(e.what()));
    }
    a.expression = expression;
  }
  if (procedural && a.expression.empty())
    throw InputError("parameter 'anisotropy.expression' is missing (direction \"expression\" needs \"ex, ey, ez\")");
}

}  // namespace

std::vector<PanelEdit> panel_edits_from_json(std::string_view json) {
  return read_edits(parse_json(json, 4, 1 << 20));
}

RemeshParams remesh_params_from_json(std::string_view json, const RemeshParams& base) {
  const JsonValue root = parse_json(json, 4, 1 << 20);  // 1 MB: up to kMaxEdits edits
  if (root.type != JsonValue::Type::Object) throw InputError("parameters must be a JSON object");
  RemeshParams p = base;
  for (const auto& [name, value] : root.object) {
    if (name == "panels") {
      p.panels = static_cast<int>(number(value, name, 1, kMaxCount, true));
    } else if (name == "seed") {
      p.seed = static_cast<std::uint64_t>(number(value, name, 0, static_cast<double>(RemeshParams::kMaxSeed), true));
    } else if (name == "weights") {
      read_weights(value, p.weights);
    } else if (name == "lloydIterations") {
      p.lloyd_iterations = static_cast<int>(number(value, name, 0, kMaxIterations, true));
    } else if (name == "panelRounds") {
      // At least one round: without one there are no panels.
      p.panel_rounds = static_cast<int>(number(value, name, 1, kMaxIterations, true));
    } else if (name == "retries") {
      p.retries = static_cast<int>(number(value, name, 0, RemeshParams::kMaxRetries, true));
    } else if (name == "seeding") {
      if (value.type != JsonValue::Type::String || (value.string != "farthest" && value.string != "random"))
        throw InputError("parameter 'seeding' must be \"farthest\" or \"random\"");
      p.seeding = value.string == "random" ? SeedingMethod::Random : SeedingMethod::FarthestPoint;
    } else if (name == "teleport") {
      p.teleport_interval = boolean(value, name) ? RemeshParams{}.teleport_interval : 0;
    } else if (name == "singlePointNodes") {
      p.single_point_nodes = boolean(value, name);
    } else if (name == "optimizePlanes") {
      p.optimize_planes = boolean(value, name);
    } else if (name == "edits") {
      p.edits = read_edits(value);
    } else if (name == "glass") {
      p.glass = boolean(value, name);  // glass mode: concave panels cut into convex pieces
    } else if (name == "minCornerAngleDeg") {
      p.min_corner_angle_deg = number(value, name, 0, 60, false);  // as the CLI's --min-angle
    } else if (name == "coplanarAngleDeg") {
      p.coplanar_angle_deg = number(value, name, 0, 10, false);  // as the CLI's --coplanar-angle
    } else if (name == "densityExpression") {
      if (value.type != JsonValue::Type::String) throw InputError("parameter 'densityExpression' must be a string");
      // Checked here (length, syntax, names) so a bad link fails with its own message.
      if (!value.string.empty()) Expression::parse(value.string);
      p.density_expression = value.string;
    } else if (name == "anisotropy") {
      read_anisotropy(value, p.anisotropy);
    } else {
      throw InputError("unknown parameter '" + name + "'");
    }
  }
  return p;
}

}  // namespace ff
