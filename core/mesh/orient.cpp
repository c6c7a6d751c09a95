#include "core/mesh/orient.h"

#include <Eigen/Geometry>
#include <utility>

#include "core/util/error.h"

namespace ff::detail {

OrientResult orient_faces(std::vector<Triangle>& tris, const HalfEdgeGroups& groups, const std::vector<Vec3>& positions,
                          const std::vector<int>& vertex_name, bool closed_outward) {
  const size_t m = tris.size();
  // flip[f]: -1 unvisited, else 1 when f must be flipped relative to its component's seed.
  std::vector<signed char> flip(m, -1);
  std::vector<int> component(m), seed_face;
  std::vector<char> closed;
  std::vector<int> queue;
  queue.reserve(m);

  for (size_t seed = 0; seed < m; ++seed) {
    if (flip[seed] >= 0) continue;
    const int c = static_cast<int>(seed_face.size());
    seed_face.push_back(static_cast<int>(seed));
    closed.push_back(1);
    flip[seed] = 0;
    component[seed] = c;
    queue.assign(1, static_cast<int>(seed));
    for (size_t q = 0; q < queue.size(); ++q) {
      const int f = queue[q];
      for (int i = 0; i < 3; ++i) {
        const int h = 3 * f + i;
        const int g = groups.edge_of[static_cast<size_t>(h)];
        if (groups.group_size(g) < 2) {
          closed.back() = 0;
          continue;
        }
        const int twin = groups.first(g) == h ? groups.second(g) : groups.first(g);
        const auto o = static_cast<size_t>(twin / 3);
        // Agreeing neighbours run the shared edge in opposite directions.
        const bool same_direction = tail_of(tris, h) == tail_of(tris, twin);
        const auto need = static_cast<signed char>(flip[static_cast<size_t>(f)] ^ (same_direction ? 1 : 0));
        if (flip[o] < 0) {
          flip[o] = need;
          component[o] = c;
          queue.push_back(static_cast<int>(o));
        } else if (flip[o] != need) {
          const int v = tail_of(tris, h);
          throw InputError("the surface is not orientable (like a Moebius strip) near vertex " +
                           std::to_string(vertex_name[static_cast<size_t>(v)]) + " at " +
                           format_point(positions[static_cast<size_t>(v)]));
        }
      }
    }
  }

  // Which of its two consistent orientations each component keeps. One pass in face
  // order (not BFS order) to stay cache-friendly on large meshes.
  const size_t num_components = seed_face.size();
  const auto corner = [&](size_t f, size_t i) -> const Vec3& { return positions[static_cast<size_t>(tris[f][i])]; };
  std::vector<double> volume(num_components, 0.0), area_kept(num_components, 0.0), area_flipped(num_components, 0.0);
  std::vector<int> faces(num_components, 0), faces_flipped(num_components, 0);
  for (size_t f = 0; f < m; ++f) {
    const auto c = static_cast<size_t>(component[f]);
    const Vec3& origin = corner(static_cast<size_t>(seed_face[c]), 0);  // nearby: precision
    const Vec3 a = corner(f, 0) - origin, b = corner(f, 1) - origin, cc = corner(f, 2) - origin;
    const double area = (b - a).cross(cc - a).norm();
    const double signed_volume = a.dot(b.cross(cc));
    ++faces[c];
    if (flip[f]) {
      volume[c] -= signed_volume;
      area_flipped[c] += area;
      ++faces_flipped[c];
    } else {
      volume[c] += signed_volume;
      area_kept[c] += area;
    }
  }
  std::vector<char> invert(num_components, 0);
  for (size_t c = 0; c < num_components; ++c) {
    if (closed[c] && closed_outward && volume[c] != 0.0) {
      invert[c] = volume[c] < 0.0;
    } else if (area_flipped[c] != area_kept[c]) {
      invert[c] = area_flipped[c] > area_kept[c];
    } else {
      invert[c] = 2 * faces_flipped[c] > faces[c];
    }
  }

  OrientResult result;
  result.components = static_cast<int>(num_components);
  for (size_t f = 0; f < m; ++f) {
    if ((flip[f] != 0) == (invert[static_cast<size_t>(component[f])] != 0)) continue;
    std::swap(tris[f][1], tris[f][2]);
    ++result.faces_flipped;
  }
  return result;
}

}  // namespace ff::detail
