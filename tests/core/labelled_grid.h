// A mesh cut into clusters by a rule on its face centroids, with its topology and panel
// graph: the fixture the panel-layout unit tests build their hand-placed planes on.
#pragma once

#include <utility>
#include <vector>

#include "core/mesh/topology.h"
#include "core/mesh/tri_mesh.h"
#include "core/panels/panel_graph.h"

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

}  // namespace ff::test
