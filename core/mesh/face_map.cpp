#include "core/mesh/face_map.h"

namespace ff {

std::vector<int> values_for_input_faces(const CleanMesh& clean, const TriMesh& input,
                                        const MeshTopology& clean_topology, const std::vector<int>& values) {
  std::vector<int> out(input.triangles.size(), values.empty() ? 0 : values.front());
  for (size_t f = 0; f < input.triangles.size(); ++f) {
    const int kept = clean.input_face_to_clean[f];
    if (kept >= 0) {
      out[f] = values[static_cast<size_t>(kept)];
      continue;
    }
    if (f < clean.input_face_outside_part.size() && clean.input_face_outside_part[f]) {
      out[f] = -1;
      continue;
    }
    for (int v : input.triangles[f]) {
      const int cv = v >= 0 && static_cast<size_t>(v) < clean.input_vertex_to_clean.size()
                         ? clean.input_vertex_to_clean[static_cast<size_t>(v)]
                         : -1;
      if (cv < 0) continue;
      const int begin = clean_topology.vertex_face_offsets[static_cast<size_t>(cv)];
      const int end = clean_topology.vertex_face_offsets[static_cast<size_t>(cv) + 1];
      if (begin < end) {
        out[f] = values[static_cast<size_t>(clean_topology.vertex_faces[static_cast<size_t>(begin)])];
        break;
      }
    }
  }
  return out;
}

std::vector<double> values_for_clean_vertices(const CleanMesh& clean, const std::vector<double>& input_values) {
  std::vector<double> sum(clean.mesh.positions.size(), 0.0);
  std::vector<int> count(clean.mesh.positions.size(), 0);
  for (size_t v = 0; v < input_values.size() && v < clean.input_vertex_to_clean.size(); ++v) {
    const int cv = clean.input_vertex_to_clean[v];
    if (cv < 0) continue;
    sum[static_cast<size_t>(cv)] += input_values[v];
    ++count[static_cast<size_t>(cv)];
  }
  for (size_t v = 0; v < sum.size(); ++v) {
    // A copy made when splitting a non-manifold vertex has no input vertex of its own.
    sum[v] = count[v] > 0 ? sum[v] / count[v] : input_values[static_cast<size_t>(clean.vertex_source[v])];
  }
  return sum;
}

std::vector<double> values_for_clean_faces(const CleanMesh& clean, const std::vector<double>& input_values) {
  std::vector<double> out(clean.face_source.size());
  for (size_t f = 0; f < out.size(); ++f) out[f] = input_values[static_cast<size_t>(clean.face_source[f])];
  return out;
}

}  // namespace ff
