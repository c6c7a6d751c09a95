#pragma once
// Splitting a node where k >= 4 clusters meet into k - 2 valence-3 nodes joined by short new
// edges (paper fig. 6): each way to do it is a triangulation of the k-gon of clusters around
// the node (positions 0..k-1 in counter-clockwise order); a triangle is a node on its three
// planes, a diagonal a new edge between its two clusters. A boundary node is the fan from
// the NULL cluster is one of the choices (fan_pairing), not the only one: PanelLayout tries
// every triangulation of boundary groups too, and its checks decide.
#include <array>
#include <vector>

namespace ff {

using NodeTriangle = std::array<int, 3>;  // positions around the node, increasing
using Pairing = std::vector<NodeTriangle>;

// Every triangulation of the k-gon for k <= 7 (Catalan(k-2): 2, 5, 14, 42), the k fans
// beyond. In a fixed order, so choices are deterministic. k == 3: the one triangle.
std::vector<Pairing> node_pairings(int k);

// The fan from position k-1 (a boundary node's NULL cluster).
Pairing fan_pairing(int k);

// The triangles of `pairing` containing position i, in the order a panel's boundary meets
// them: from the one with position i+1 to the one with position i-1 (mod k).
std::vector<int> triangles_around(const Pairing& pairing, int k, int i);
// The same into `out` (cleared first), for the hot loop that lays out every panel.
void triangles_around(const Pairing& pairing, int k, int i, std::vector<int>& out);

// Keeps in `options` (pairings of the k-gon `clusters`, counter-clockwise) those whose nodes
// include every cluster triple of `held` (sorted) that lies in the k-gon, so a locked panel's
// corners stay the nodes they were. True when any triple lies in it and some pairing has
// them all; else `options` is left as it was.
bool hold_pairings(const std::vector<int>& clusters, const std::vector<std::array<int, 3>>& held,
                   std::vector<Pairing>& options);

}  // namespace ff
