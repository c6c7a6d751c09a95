#pragma once
// Carrying per-face results of the cleaned mesh back to the faces of the input file, so
// outputs (labels files, colours) line up with what the designer loaded.
#include <vector>

#include "core/mesh/clean.h"
#include "core/mesh/topology.h"

namespace ff {

// values[f] per cleaned face -> one value per input face. An input face that clean-up
// dropped (degenerate or duplicate) takes the value of the lowest-numbered cleaned face
// around its first surviving vertex (its twin or neighbour), or values[0] if none survives;
// one left out with its part (CleanOptions::largest_manifold_part) takes -1.
std::vector<int> values_for_input_faces(const CleanMesh& clean, const TriMesh& input,
                                        const MeshTopology& clean_topology, const std::vector<int>& values);

// Per-input-vertex values (e.g. painted density) -> per cleaned vertex, averaging input
// vertices that were welded together.
std::vector<double> values_for_clean_vertices(const CleanMesh& clean, const std::vector<double>& input_values);

// Per-input-face values -> per cleaned face.
std::vector<double> values_for_clean_faces(const CleanMesh& clean, const std::vector<double>& input_values);

}  // namespace ff
