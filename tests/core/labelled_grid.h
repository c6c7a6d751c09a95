// A mesh cut into clusters by a rule on its face centroids, with its topology and panel
// graph: the fixture the panel-layout unit tests build their hand-placed planes on.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "core/mesh/topology.h"
#include "core/mesh/tri_mesh.h"
#include "core/panels/panel_graph.h"
#include "core/panels/panel_layout.h"
#include "synthetic_meshes.h"

namespace ff::test {

struct LabelledGrid {
  TriMesh mesh;
  MeshTopology topology;
  std::vector<int> labels;  // per face, in [0, clusters)
  PanelGraph graph;
};

// `label_of(centroid)` gives each face of `mesh` its cluster, one of `clusters`.
template <class LabelOf>
LabelledGrid labelled_grid(TriMesh mesh, int clusters, LabelOf label_of) {
  LabelledGrid g;
  g.mesh = std::move(mesh);
  g.topology = build_topology(g.mesh);
  for (int f = 0; f < g.mesh.num_faces(); ++f) g.labels.push_back(label_of(face_centroid(g.mesh, f)));
  g.graph = build_panel_graph(g.mesh, g.topology, g.labels, clusters);
  return g;
}

// An nx x ny grid of cells 0.5 wide on z = 0 (chains of a few cells stay longer than the
// tests' spike distances).
inline TriMesh half_grid(int nx, int ny) {
  TriMesh m = grid(nx, ny);
  for (Vec3& p : m.positions) p *= 0.5;
  return m;
}

// Every panel's vertices on its plane (the vertex rule): exactly planar to `tolerance`.
inline void expect_planar(const PanelLayout& layout, double tolerance) {
  for (int c = 0; c < layout.num_clusters(); ++c) {
    const Plane& plane = layout.planes().plane_of(c);
    for (const Vec3& v : layout.polygon(c).points) EXPECT_LT(std::abs(plane.distance(v)), tolerance) << c;
  }
}

// The notch of the aim tests: 12 x 8 cells of 0.5 (chains long enough to be their own nodes)
// in four clusters, P (0) below y = 2, and above it A (1, x < 2), Q (2, 2 < x < 4) and
// B (3, x > 4).
inline LabelledGrid notch_grid() {
  return labelled_grid(half_grid(12, 8), 4,
                       [](const Vec3& c) { return c.y() < 2.0 ? 0 : (c.x() < 2.0 ? 1 : (c.x() < 4.0 ? 2 : 3)); });
}

}  // namespace ff::test
