#include "wasm/mesh_arrays.h"

#include <array>

#include "core/util/error.h"

namespace ff::wasm {

TriMesh mesh_from_arrays(const std::string& prefix, const std::vector<double>& positions,
                         const std::vector<std::uint32_t>& indices) {
  if (positions.size() % 3 != 0) throw InputError(prefix + "positions are not xyz triples");
  if (indices.size() % 3 != 0) throw InputError(prefix + "indices are not triangles");
  TriMesh mesh;
  mesh.positions.reserve(positions.size() / 3);
  for (size_t i = 0; i < positions.size(); i += 3) {
    const Vec3 p(positions[i], positions[i + 1], positions[i + 2]);
    if (!p.allFinite()) throw InputError(prefix + "vertex " + std::to_string(i / 3) + " is not finite");
    mesh.positions.push_back(p);
  }
  mesh.triangles.reserve(indices.size() / 3);
  for (size_t i = 0; i < indices.size(); i += 3) {
    std::array<int, 3> t{};
    for (size_t k = 0; k < 3; ++k) {
      if (indices[i + k] >= mesh.positions.size())
        throw InputError(prefix + "triangle " + std::to_string(i / 3) + " uses a missing vertex");
      t[k] = static_cast<int>(indices[i + k]);
    }
    mesh.triangles.push_back(t);
  }
  return mesh;
}

}  // namespace ff::wasm
