#pragma once
// The L2,1 energy of a partition, computed from the triangles alone so both libraries'
// partitions are scored by the same code: sum over faces of area * |n_f - N_i|^2, with N_i
// the normalised area-weighted mean normal of the face's cluster (its optimal L2,1 proxy).
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff::bench {

// A negative value when labels are not a partition into n non-empty clusters.
double l21_energy(const TriMesh& mesh, const std::vector<int>& labels, int n);

}  // namespace ff::bench
