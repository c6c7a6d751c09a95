#include "core/fabricate/panel_edges.h"

#include <algorithm>
#include <map>
#include <utility>

namespace ff {

PanelEdges panel_edges(const PanelMesh& pm) {
  PanelEdges e;
  e.neighbour.resize(pm.panels.size());
  e.vertex_panels.resize(pm.vertices.size());
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> by_edge;  // (panel, edge)
  for (size_t p = 0; p < pm.panels.size(); ++p) {
    const std::vector<int>& poly = pm.panels[p];
    e.neighbour[p].assign(poly.size(), -1);
    for (size_t i = 0; i < poly.size(); ++i) {
      const int a = poly[i], b = poly[(i + 1) % poly.size()];
      by_edge[{std::min(a, b), std::max(a, b)}].push_back({static_cast<int>(p), static_cast<int>(i)});
      std::vector<int>& around = e.vertex_panels[static_cast<size_t>(a)];
      if (around.empty() || around.back() != static_cast<int>(p)) around.push_back(static_cast<int>(p));
    }
  }
  for (const auto& [key, uses] : by_edge) {
    if (uses.size() != 2 || uses[0].first == uses[1].first) continue;
    e.neighbour[static_cast<size_t>(uses[0].first)][static_cast<size_t>(uses[0].second)] = uses[1].first;
    e.neighbour[static_cast<size_t>(uses[1].first)][static_cast<size_t>(uses[1].second)] = uses[0].first;
  }
  return e;
}

}  // namespace ff
