#pragma once
// A mesh index (int, as the meshes store them) as a container position: one cast, said once.
#include <cstddef>

namespace ff {

inline size_t at(int i) { return static_cast<size_t>(i); }

}  // namespace ff
