#pragma once
// Plane relaxation: move the planes so that the nodes they define land near their corners,
// while each plane still fits its surface. On near-developable parts of a surface (a gently
// curved roof, a cylinder), the normals of three neighbouring clusters are nearly coplanar
// and their common point lies far from the corner however well each plane fits (the paper's
// spikes, 2.3). The paper tilts the planes of a spike towards its corner, one at a time; this
// is the same idea solved for all planes together, by a penalty method:
//
//   minimise  sum_nodes |x_k - p_k|^2 w_k  +  sum_planes E_fit(plane)
//           + W sum_nodes sum_{planes i of k} (n_i . x_k - d_i)^2
//
// alternating exact minimisation over the nodes x_k (a 3x3 solve each) and over the planes
// (a 3x3 eigenproblem each), with W growing geometrically, so the nodes end up on their
// planes. The layout then places every node exactly by the vertex rule on the relaxed planes:
// planarity stays exact; relaxation only decides which planes.
#include <array>
#include <vector>

#include "core/cluster/metric.h"
#include "core/panels/plane.h"

namespace ff {

struct NodeConstraint {
  Vec3 corner = Vec3::Zero();  // p_k: where the node should be
  std::array<int, 3> planes{{-1, -1, -1}};
  int count = 0;        // planes used (1..3)
  double weight = 1.0;  // how hard the node is pulled to its corner (raised for spikes)
};

// W runs from 1 to at most 1.4^79 (about 3e11): the nodes end up on their planes to ~1e-12 of
// D, far below what the vertex rule then corrects. Slower growth (1.1, 300 iterations) gave fewer
// valid runs in bench/sweep_validity.sh (53 of 65 against 58), at four times the cost.
struct RelaxOptions {
  int iterations = 80;
  double start_weight = 1.0;  // W at the first iteration (relative to the node terms)
  double growth = 1.4;        // W grows by this factor per iteration
  // Nodes of a plane weigh this times its area in total (against the area-integrated squared
  // distance of its faces, which the same units measure).
  double node_weight = 1.0;
  // Once W is far above the nodes' own weights the nodes sit on their planes, and each
  // iteration turns a plane by 1/growth of the last turn: the rest of the way is a geometric
  // series. When no free plane's normal or offset moved more than this in an iteration (and
  // growth is at least 1.1), the relaxation adds the series' sum (the last step times
  // 1/(growth - 1)) and stops: on bunny.off at 200 panels that lands within 1e-10 to 5e-7 of
  // all 80 iterations (stopping without the sum: 2e-6) after 44-76 of them. 0: always run
  // every iteration.
  double settled_step = 1e-6;
};

// A plane that may only turn about a line it contains (a point on it and its unit direction):
// the neighbour of a locked panel turns about their common edge line, which keeps every node
// of the locked panel where it is (remesher_edits.cpp).
struct PlaneHinge {
  bool on = false;
  Vec3 point = Vec3::Zero();
  Vec3 direction = Vec3::UnitX();
};

// planes: current planes (their normals' sides are kept); moments: the faces of each plane;
// fixed: planes that stay as they are (empty: none), e.g. around panels already valid;
// hinges: per plane (empty: none), planes not fixed that fit only within their pencil.
std::vector<Plane> relax_planes(const std::vector<NodeConstraint>& nodes, const std::vector<ClusterMoments>& moments,
                                const std::vector<Plane>& planes, const RelaxOptions& options = {},
                                const std::vector<char>& fixed = {}, const std::vector<PlaneHinge>& hinges = {});

// The plane through the hinge's line that best fits a scatter taken about the hinge's point
// (smallest eigenvector of the scatter restricted to normals across the line), on the side of
// `side`; `side` itself when the fit fails.
Plane hinged_fit(const PlaneHinge& hinge, const Eigen::Matrix3d& scatter, const Plane& side);

}  // namespace ff
