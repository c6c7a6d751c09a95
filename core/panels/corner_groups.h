#pragma once
// Node groups: where the panel mesh puts its nodes. Usually one corner of the panel graph;
// but two corners joined by a short chain (shorter than a spike) are one group, because the
// order of their two nodes along the chain's line is not decided by the clustering: whether
// clusters A-B or C-D share the short edge is exactly the "switch the neighbour assignments"
// choice of paper fig. 6. A group of k clusters has k - 2 nodes, one per triangle of a
// triangulation of its k-gon (node_split.h), and PanelLayout picks the one that flips nothing.
#include <vector>

#include "core/panels/panel_graph.h"
#include "core/panels/plane.h"

namespace ff {

struct NodeGroup {
  std::vector<int> clusters;      // counter-clockwise; kBoundary once for a boundary group
  std::vector<int> corners;       // the panel-graph corners it stands for (1 or 2)
  Vec3 reference = Vec3::Zero();  // where its nodes belong: the corner, or the chain's midpoint
  bool on_boundary = false;
  // On the boundary: the border's wall at its boundary corner (the plane through the corner
  // spanned by the border's direction and the surface normal). A boundary node lies on it,
  // "closest to the boundary" as the paper puts it (2.5), rather than merely closest to the
  // boundary vertex, which lets it slide inwards past the node at the chain's other end.
  bool has_wall = false;
  Plane wall;
};

struct NodeGroups {
  std::vector<NodeGroup> groups;
  std::vector<int> group_of_corner;  // per graph corner
};

// Corners a lock holds as they were grouped (mesh vertex ids): pairs that stay one group
// (sorted within and among), and corners that stay a group alone (sorted). Their grouping
// otherwise follows the spike distance, which moves with the panel count and the weights.
struct HeldGrouping {
  std::vector<std::pair<int, int>> together;
  std::vector<int> apart;
};

// Groups corners joined by a chain between two clusters no longer than max_chain_length
// (greedily from the shortest; each corner in at most one pair; at most 7 clusters and at
// most one boundary corner per group, and never two clusters on one master plane, whose nodes
// could coincide). positions: mesh vertices, in the frame of the length.
// `forced`: corner pairs to group whatever their chain's length (when their nodes came out in
// the wrong order, see PanelLayout::reversed_chains), tried first; `held`: as a lock holds them.
NodeGroups group_corners(const TriMesh& mesh, const MeshTopology& topology, const std::vector<int>& labels,
                         const PanelGraph& graph, const std::vector<Vec3>& positions, const std::vector<int>& master_of,
                         double max_chain_length, const std::vector<std::pair<int, int>>& forced = {},
                         const HeldGrouping& held = {});

}  // namespace ff
