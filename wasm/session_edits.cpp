// Session: per-panel edits (wasm/flatfacet.d.ts, RemeshParams.edits). Edits arrive in
// setParams' JSON with every other parameter, so the page's undo and redo are just a shorter
// or longer list; when nothing but the list changed, the design is edited in place
// (Remesher::set_edits) instead of solved again.
#include <algorithm>
#include <chrono>
#include <cstdio>

#include "core/util/json_reader.h"
#include "wasm/guarded.h"
#include "wasm/session.h"

namespace ff::wasm {

namespace {

// The value as canonical text: object members sorted by name (the last of repeated names,
// as the parameter reader takes it), numbers to 17 digits.
void canonical(const JsonValue& v, std::string& out) {
  switch (v.type) {
    case JsonValue::Type::Null:
      out += "null";
      break;
    case JsonValue::Type::Boolean:
      out += v.boolean ? "true" : "false";
      break;
    case JsonValue::Type::Number: {
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "%.17g", v.number);
      out += buffer;
      break;
    }
    case JsonValue::Type::String:
      out += '"';
      for (char c : v.string) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
      }
      out += '"';
      break;
    case JsonValue::Type::Array:
      out += '[';
      for (const JsonValue& e : v.array) canonical(e, out), out += ',';
      out += ']';
      break;
    case JsonValue::Type::Object: {
      std::vector<const std::pair<std::string, JsonValue>*> members;
      for (const auto& m : v.object) members.push_back(&m);
      std::stable_sort(members.begin(), members.end(), [](const auto* a, const auto* b) { return a->first < b->first; });
      out += '{';
      for (size_t i = 0; i < members.size(); ++i) {
        if (i + 1 < members.size() && members[i + 1]->first == members[i]->first) continue;
        out += members[i]->first + ':';
        canonical(members[i]->second, out);
        out += ',';
      }
      out += '}';
      break;
    }
  }
}

}  // namespace

std::string Session::solve_key(const std::string& params_json, int panels) {
  JsonValue root = parse_json(params_json, 4, 1 << 20);
  root.object.erase(std::remove_if(root.object.begin(), root.object.end(),
                                   [](const auto& m) { return m.first == "edits" || m.first == "panels"; }),
                    root.object.end());
  JsonValue count;
  count.type = JsonValue::Type::Number;
  count.number = panels;
  root.object.emplace_back("panels", std::move(count));
  std::string out;
  canonical(root, out);
  return out;
}

// After edits the page shows the count now (target plus splits minus merges): sent back, with
// these edits or more, it is the target unchanged (Remesher::kept_count), not a new count.
int Session::kept_target(const RemeshParams& params) const {
  if (!remesher_) return params.panels;
  RemeshParams same = params;
  same.edits = remesher_->params().edits;
  return remesher_->kept_count(same) ? remesher_->params().panels : params.panels;
}

bool Session::apply_edits_only(const std::string& key, const RemeshParams& params) {
  if (!remesher_ || key != solve_key_) return false;
  // Without edits before or after, a repeated setParams warm-starts as it always did.
  if (params.edits.empty() && remesher_->params().edits.empty()) return false;
  const auto t0 = std::chrono::steady_clock::now();
  remesher_->set_edits(params.edits);  // throws and keeps the design on a bad edit
  forget_result();
  timings_.panels = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  params_ = params;
  return true;
}

int Session::panel_of_face(int face) const {
  if (!remesher_ || face < 0 || static_cast<size_t>(face) >= remesher_->clustering().labels.size()) return -1;
  return remesher_->clustering().labels[static_cast<size_t>(face)];
}

int Session::panel_face(int panel) const {
  if (!remesher_ || panel < 0 || panel >= remesher_->num_panels()) return -1;
  return remesher_->clustering().seeds[static_cast<size_t>(panel)];
}

std::vector<std::int32_t> Session::locked_panels() const {
  if (!remesher_) return {};
  const std::vector<int> locked = remesher_->locked_clusters();
  return std::vector<std::int32_t>(locked.begin(), locked.end());
}

// The selected panel on the page is a triangle; its panel in the panel mesh (glass pieces and
// unbuilt clusters apart from clusterIds) is what the per-panel thickness names.
std::vector<std::int32_t> Session::face_panels() const {
  std::vector<std::int32_t> out(mesh_.triangles.size(), -1);
  if (!remesher_) return out;
  const std::vector<int>& face_panel = remesher_->panels().face_panel;
  for (size_t f = 0; f < out.size() && f < face_panel.size(); ++f) out[f] = face_panel[f];
  return out;
}

int Session::panel_count() const { return remesher_ ? remesher_->num_panels() : 0; }

}  // namespace ff::wasm
