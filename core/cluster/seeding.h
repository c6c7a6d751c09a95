#pragma once
// Initial seeds (paper 2: "place n seeds"). Every connected component gets seeds in
// proportion to its area and at least one, so flooding reaches every face (four on a closed
// part when n allows: fewer cannot become valid panels). With a density
// field (density_weight = the metric's density weight w), area counts as area * density^w
// and distances as length * sqrt(density^w): dense regions start with as many seeds as the
// panel sizes they ask for, instead of waiting for Lloyd to move seeds across.
//   Random:        area-weighted random faces from our PRNG (what CGAL's VSA and the
//                  paper do), for comparison and benchmarks.
//   FarthestPoint: the first seed of a component at random, each next one the face
//                  farthest (geodesically, over the face-adjacency graph) from all seeds
//                  so far; an even spread that makes Lloyd converge in fewer iterations.
#include <cstdint>
#include <vector>

#include "core/cluster/face_data.h"
#include "core/mesh/topology.h"

namespace ff {

enum class SeedingMethod { Random, FarthestPoint };

// Seeds per component: largest-remainder split of n by area, at least each part's floor
// (cluster_floors, topology.h: four on a closed part when n allows, else one). Throws
// InputError when n < number of components or n > number of faces.
std::vector<int> seeds_per_component(const FaceData& faces, const MeshTopology& topology, int n,
                                     double density_weight = 0.0);

// n distinct seed faces. Deterministic for a given seed value.
std::vector<int> place_seeds(const FaceData& faces, const MeshTopology& topology, int n, SeedingMethod method,
                             std::uint64_t seed, double density_weight = 0.0);

}  // namespace ff
