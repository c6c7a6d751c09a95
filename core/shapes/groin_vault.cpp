// Groin vault: two barrel vaults crossing over a square bay. The intrados is the top of the
// union of the two tunnels, z = max(arc(x), arc(y)) = arc(min(|x|, |y|)), with its sharp
// groins over the bay's diagonals. (The min would be a cloister vault, creased the other
// way and flat to the walls.) An even square grid whose cells are split along the diagonal
// parallel to the nearer bay diagonal has both bay diagonals among its edges, so each
// triangle lies on one vault only and the creases stay exactly sharp.
#include <algorithm>
#include <cmath>

#include "core/shapes/hard_cases.h"
#include "core/shapes/shapes.h"
#include "core/util/error.h"

namespace ff {

TriMesh make_groin_vault(int triangles, double span, double rise) {
  const double half = span / 2.0;
  if (!(span > 0.0) || !(rise > 0.0) || !(rise <= half))
    throw InputError("groin vault: need span > 0 and 0 < rise <= span / 2");
  // Height of the circular arc through (+-half, 0) and (0, rise) above offset s from the middle.
  const double radius = (half * half + rise * rise) / (2.0 * rise);
  const auto arc = [&](double s) { return std::sqrt(std::max(0.0, radius * radius - s * s)) - (radius - rise); };

  const int n = grid_dims_for(triangles, span, span, 2, 2)[0];
  TriMesh mesh;
  mesh.positions.reserve(static_cast<size_t>(n + 1) * static_cast<size_t>(n + 1));
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      // x and y from the same expression, so diagonal vertices have |x| == |y| exactly.
      const double x = (2.0 * i - n) * half / n, y = (2.0 * j - n) * half / n;
      mesh.positions.emplace_back(x, y, arc(std::min(std::abs(x), std::abs(y))));
    }
  }
  const auto id = [n](int i, int j) { return j * (n + 1) + i; };
  mesh.triangles.reserve(2 * static_cast<size_t>(n) * static_cast<size_t>(n));
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      // Cell centre in the quadrants x*y > 0: the nearer bay diagonal runs like a-c.
      const bool rising = (2 * i + 1 - n) * (2 * j + 1 - n) > 0;
      add_split_quad(mesh, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), rising);
    }
  }
  return mesh;
}

}  // namespace ff
