#pragma once
// Where the panel rounds change the clustering after a failed attempt (Remesher::fix_panels):
// the clusters to move elsewhere and the splits to make.
#include <utility>
#include <vector>

#include "core/mesh/topology.h"
#include "core/mesh/tri_mesh.h"

namespace ff {

class PanelAttempt;

// Clusters enclosed by a single neighbour: to be moved elsewhere (relocate_clusters).
std::vector<int> enclosed_clusters(const PanelAttempt& attempt);

// Invalid panels whose clusters are too small to split near their problem (fewer faces than
// the mean cluster's / `share`), not enclosed: to be moved elsewhere like enclosed ones. A
// one-face cluster between three others is a triangle that the planes around it can flip,
// and no split can fix.
std::vector<int> tiny_invalid_clusters(const PanelAttempt& attempt, int share);

// How many invalid panels a stall of the panel rounds may split near (the `max_geometric` of
// split_requests(); with a minimum corner angle the rounds ask 3 whatever the count): one per
// 100 panels, 1 to 3. Each split merges a pair elsewhere and refloods both places, so it
// reshuffles a share of the clustering that shrinks as the panel count grows. Measured
// (bench/panel_rounds_profile.md, "One split per 100 panels"): at 200 panels and up a stall
// often waits on two or three places at once (bunny.off at 200, seed 7: three far apart for 28
// rounds), and splitting near each ends the rounds sooner; below, more than one split at a
// time left cow.off's runs (46-122 panels) invalid more often.
int stall_splits(int num_clusters);

// The clusters that are not disks (and not merely enclosed: an enclosed one is fixed by
// splitting the one around it, which has a hole), each found once per round.
struct ClusterCuts {
  // (cluster, face) requests for split_near(). A cluster that meets one neighbour in two
  // separate chains is cut at the middle of its chain with that neighbour farthest from its
  // seed (cut off it, the halves meet the neighbour once each); any other at its face
  // farthest from its seed. The first requests of split_requests().
  std::vector<std::pair<int, int>> cuts;
  // Those that cannot be cut: the face to cut at would be the seed (a one-face cluster whose
  // edges meet one neighbour twice). They are moved elsewhere like enclosed ones; asking for a
  // cut that split_near() skips left one at inspired_mesh.obj (100 panels, seed 5) for 9 panel
  // rounds.
  std::vector<int> uncuttable;
};
ClusterCuts cluster_cuts(const TriMesh& mesh, const MeshTopology& topology, const PanelAttempt& attempt);

// Where to split after a failed attempt: (cluster, face) requests for split_near(). First
// `cuts` (ClusterCuts::cuts of this attempt), then an invalid panel at a face next to its
// problem corner, one split per corner, at most `max_geometric` of those.
// `keep` (per cluster, empty for none): clusters never to split (held by a lock): the
// geometric splits go to the other invalid panels first, then to a free cluster at a kept
// panel's problem corner.
std::vector<std::pair<int, int>> split_requests(const TriMesh& mesh, const MeshTopology& topology,
                                                const PanelAttempt& attempt,
                                                const std::vector<std::pair<int, int>>& cuts, int max_geometric,
                                                const std::vector<char>& keep = {});

}  // namespace ff
