// hausdorff_where: where is the two-sided Hausdorff distance of our panels attained? For one
// bench_remesh case (same read + clean, default RemeshParams with the case's panel count and
// the seed, 1 unless --seed),
// prints both directed maxima with the worst sample, the panel nearest to it, that panel's
// shape (vertex count, diameter, boundary vertices, plane count of its vertices) and how far
// the sample is from the input's boundary, plus the top few panels by their own worst
// distance. A diagnostic for issue 3, not part of the table.
//
//   hausdorff_where [--meshes DIR] [--top K] [--seed S] CASE...  (CASE as in bench_remesh --cases)
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <string>
#include <vector>

#include "bench/remesh_case.h"
#include "core/mesh/tri_mesh.h"
#include "core/quality/closest_point.h"
#include "core/quality/hausdorff.h"
#include "core/remesher.h"

namespace {

struct Worst {
  double distance = 0.0;
  ff::Vec3 sample = ff::Vec3::Zero();
  int triangle = -1;  // nearest triangle of the other side
};

// Per triangle of `to`'s side: the largest distance of a sample of `from` that lands on it.
std::vector<Worst> per_target(const std::vector<ff::Vec3>& samples, const ff::TriangleTree& tree, int targets) {
  std::vector<Worst> out(static_cast<size_t>(targets));
  for (const ff::Vec3& s : samples) {
    const ff::ClosestPoint c = tree.closest_point(s);
    Worst& w = out[static_cast<size_t>(c.triangle)];
    if (c.distance > w.distance) w = {c.distance, s, c.triangle};
  }
  return out;
}

// The input's border edges: edges used by one triangle (the mesh is clean: edge-manifold).
std::vector<std::pair<ff::Vec3, ff::Vec3>> border_edges(const ff::TriMesh& mesh) {
  std::vector<std::pair<int, int>> edges;
  for (const ff::Triangle& t : mesh.triangles) {
    for (int i = 0; i < 3; ++i) {
      const int a = t[static_cast<size_t>(i)], b = t[static_cast<size_t>((i + 1) % 3)];
      edges.push_back({std::min(a, b), std::max(a, b)});
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<std::pair<ff::Vec3, ff::Vec3>> out;
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i == 1) {
      out.push_back({mesh.positions[static_cast<size_t>(edges[i].first)],
                     mesh.positions[static_cast<size_t>(edges[i].second)]});
    }
    i = j;
  }
  return out;
}

double distance_to_border(const std::vector<std::pair<ff::Vec3, ff::Vec3>>& border, const ff::Vec3& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& [a, b] : border) {
    const ff::Vec3 ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
    best = std::min(best, (a + t * ab - p).norm());
  }
  return best;
}

void describe_panel(const ff::PanelMesh& pm, int p, double diag) {
  const std::vector<int>& poly = pm.panels[static_cast<size_t>(p)];
  double diameter = 0.0;
  int planes[4] = {0, 0, 0, 0};
  double worst_ref = 0.0;
  for (int a : poly) {
    for (int b : poly) diameter = std::max(diameter, (pm.vertices[size_t(a)] - pm.vertices[size_t(b)]).norm());
    planes[std::clamp(pm.vertex_planes[size_t(a)], 0, 3)]++;
    if (!pm.vertex_reference.empty())
      worst_ref = std::max(worst_ref, (pm.vertices[size_t(a)] - pm.vertex_reference[size_t(a)]).norm());
  }
  std::printf("    panel %d (cluster %d): %zu vertices (1-plane %d, 2-plane %d, 3-plane %d), diameter %.4f, "
              "max vertex-to-corner %.5f (spike limit %.5f), valid %d\n",
              p, pm.panel_cluster[size_t(p)], poly.size(), planes[1], planes[2], planes[3], diameter / diag,
              worst_ref / diag, pm.spike_distance / diag, pm.issues[size_t(p)].valid() ? 1 : 0);
}

void run_case(const std::string& name, const std::string& meshes, int top, std::uint64_t seed) {
  ff::bench::RemeshCase c;
  if (!ff::bench::parse_remesh_case(name, c)) {
    std::fprintf(stderr, "unknown case %s\n", name.c_str());
    std::exit(2);
  }
  ff::TriMesh input = ff::bench::load_remesh_case(c, meshes);
  ff::RemeshParams params;
  params.panels = c.panels;
  params.seed = seed;
  ff::Remesher remesher(input, params);
  remesher.run();
  const ff::PanelMesh& pm = remesher.panels();
  const double diag = ff::bbox_diagonal(input);
  std::vector<int> tri_panel;
  const ff::TriMesh panels_tri = ff::triangulate_panels(pm, &tri_panel);
  const ff::HausdorffResult h = ff::hausdorff_distance(input, pm);
  std::printf("%s: %d panels, %d invalid; Hausdorff %.5f (input->panels %.5f, panels->input %.5f)\n",
              c.label.c_str(), pm.num_panels(), pm.num_invalid(), h.two_sided, h.input_to_panels,
              h.panels_to_input);

  const ff::TriangleTree to_panels(panels_tri), to_input(input);
  const auto border = border_edges(input);
  const auto in_samples = ff::sample_surface(input, 200000, 0x48617573646F7266ULL);
  const auto out_samples = ff::sample_surface(panels_tri, 200000, 0x6F72666653696465ULL);

  // input -> panels, grouped by the panel of the nearest panel triangle.
  std::vector<Worst> by_tri = per_target(in_samples, to_panels, panels_tri.num_faces());
  std::vector<Worst> by_panel(size_t(pm.num_panels()));
  for (const Worst& w : by_tri) {
    if (w.triangle < 0) continue;
    Worst& b = by_panel[size_t(tri_panel[size_t(w.triangle)])];
    if (w.distance > b.distance) b = w;
  }
  // panels -> input: a sample's panel is the panel of the panel triangle it was drawn on; find
  // it as the nearest panel triangle (distance 0).
  std::vector<Worst> out_by_panel(size_t(pm.num_panels()));
  for (const ff::Vec3& s : out_samples) {
    const ff::ClosestPoint on_input = to_input.closest_point(s);
    const ff::ClosestPoint own = to_panels.closest_point(s);
    Worst& b = out_by_panel[size_t(tri_panel[size_t(own.triangle)])];
    if (on_input.distance > b.distance) b = {on_input.distance, s, on_input.triangle};
  }
  // away_from_border > 0: only samples at least that far (fraction of the diagonal) from the
  // input's border, to see the interior apart from the border loops.
  auto report = [&](const char* title, std::vector<Worst> list, double away_from_border) {
    std::vector<int> order;
    for (size_t i = 0; i < list.size(); ++i) {
      if (away_from_border > 0.0 && distance_to_border(border, list[i].sample) < away_from_border * diag) continue;
      order.push_back(static_cast<int>(i));
    }
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return list[size_t(a)].distance > list[size_t(b)].distance; });
    std::printf("  %s, worst panels%s:\n", title, away_from_border > 0.0 ? " away from the border" : "");
    for (int k = 0; k < top && k < static_cast<int>(order.size()); ++k) {
      const Worst& w = list[size_t(order[size_t(k)])];
      std::printf("   %.5f at (%.3f, %.3f, %.3f), %.4f from the input border\n", w.distance / diag, w.sample.x(),
                  w.sample.y(), w.sample.z(), distance_to_border(border, w.sample) / diag);
      describe_panel(pm, order[size_t(k)], diag);
    }
  };
  report("input -> panels", by_panel, 0.0);
  report("panels -> input", out_by_panel, 0.0);
  report("input -> panels", by_panel, 0.02);
  report("panels -> input", out_by_panel, 0.02);
}

}  // namespace

int main(int argc, char** argv) {
  std::string meshes = FF_DEFAULT_SHARED_MESHES;
  if (const char* env = std::getenv("FF_SHARED_MESHES")) meshes = env;
  int top = 5;
  std::uint64_t seed = 1;
  std::vector<std::string> cases;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--meshes" && i + 1 < argc) {
      meshes = argv[++i];
    } else if (a == "--top" && i + 1 < argc) {
      top = std::atoi(argv[++i]);
    } else if (a == "--seed" && i + 1 < argc) {
      seed = std::strtoull(argv[++i], nullptr, 10);
    } else {
      cases.push_back(a);
    }
  }
  if (cases.empty()) cases.push_back("hyperboloid");
  try {
    for (const std::string& c : cases) run_case(c, meshes, top, seed);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hausdorff_where: %s\n", e.what());
    return 1;
  }
  return 0;
}
