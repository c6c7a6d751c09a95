#include "bench/cgal_vsa.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Variational_shape_approximation.h>

#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace ff::bench {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using VertexPointMap = boost::property_map<Mesh, boost::vertex_point_t>::type;
using L21Metric = CGAL::Surface_mesh_approximation::L21_metric_plane_proxy<Mesh>;
using Approximation = CGAL::Variational_shape_approximation<Mesh, VertexPointMap, L21Metric>;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

CgalVsaRun run_cgal_vsa(const ff::TriMesh& input, int panels, int iterations, unsigned seed) {
  CgalVsaRun out;
  auto start = std::chrono::steady_clock::now();
  Mesh mesh;
  mesh.reserve(static_cast<Mesh::size_type>(input.num_vertices()),
               static_cast<Mesh::size_type>(3 * input.num_faces() / 2 + 16),
               static_cast<Mesh::size_type>(input.num_faces()));
  std::vector<Mesh::Vertex_index> vertex(input.positions.size());
  for (size_t v = 0; v < input.positions.size(); ++v) {
    const ff::Vec3& p = input.positions[v];
    vertex[v] = mesh.add_vertex(Point(p.x(), p.y(), p.z()));
  }
  for (size_t f = 0; f < input.triangles.size(); ++f) {
    const ff::Triangle& t = input.triangles[f];
    const Mesh::Face_index face = mesh.add_face(vertex[static_cast<size_t>(t[0])], vertex[static_cast<size_t>(t[1])],
                                                vertex[static_cast<size_t>(t[2])]);
    if (face == Mesh::null_face() || static_cast<size_t>(face) != f) {
      throw std::runtime_error("CGAL Surface_mesh refused face " + std::to_string(f) + " (not a manifold mesh?)");
    }
  }
  const VertexPointMap vpm = get(boost::vertex_point, mesh);
  const L21Metric metric(mesh, vpm);
  out.build_seconds = seconds_since(start);

  start = std::chrono::steady_clock::now();
  Approximation vsa(mesh, vpm, metric);
  std::srand(seed);
  out.proxies =
      static_cast<int>(vsa.initialize_seeds(CGAL::parameters::seeding_method(CGAL::Surface_mesh_approximation::RANDOM)
                                                .max_number_of_proxies(static_cast<std::size_t>(panels))
                                                .number_of_relaxations(0)));
  out.seed_seconds = seconds_since(start);

  for (int it = 0; it < iterations; ++it) {
    start = std::chrono::steady_clock::now();
    out.cgal_error = vsa.run(1);
    out.iteration_seconds.push_back(seconds_since(start));
  }

  auto proxy_of = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  vsa.proxy_map(proxy_of);
  out.labels.resize(input.triangles.size());
  for (Mesh::Face_index f : mesh.faces()) {
    const std::size_t p = get(proxy_of, f);
    out.labels[static_cast<size_t>(f)] = p < static_cast<std::size_t>(out.proxies) ? static_cast<int>(p) : -1;
  }
  return out;
}

std::string cgal_version() { return CGAL_VERSION_STR; }

}  // namespace ff::bench
