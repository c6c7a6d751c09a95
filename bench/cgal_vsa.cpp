#include "bench/cgal_vsa.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Variational_shape_approximation.h>

#include <cstdlib>
#include <iterator>
#include <set>
#include <stdexcept>
#include <string>

#include "bench/stopwatch.h"

namespace ff::bench {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using VertexPointMap = boost::property_map<Mesh, boost::vertex_point_t>::type;
using L21Metric = CGAL::Surface_mesh_approximation::L21_metric_plane_proxy<Mesh>;
using Approximation = CGAL::Variational_shape_approximation<Mesh, VertexPointMap, L21Metric>;

// Faces of the TriMesh become CGAL faces in the same order (so labels map back one to one).
void build_surface_mesh(const ff::TriMesh& input, Mesh& mesh) {
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
}

// The boundary cycles of the proxy regions walked the way CGAL's find_edges() walks them
// (same candidate set order, same turn rule at each vertex), keeping the proxy of each: CGAL
// only hands out the anchor polygons, not which region each one bounds.
template <typename FaceProxyMap>
void boundary_cycles(const Mesh& mesh, const FaceProxyMap& proxy_of, const std::vector<std::size_t>& anchor_of,
                     CgalVsaMesh& out) {
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  const auto region = [&](Mesh::Halfedge_index h) { return get(proxy_of, mesh.face(h)); };
  const auto anchor = [&](Mesh::Halfedge_index h) { return anchor_of[static_cast<std::size_t>(mesh.target(h))]; };
  // CGAL's walk_to_next_border_halfedge.
  const auto next_border = [&](Mesh::Halfedge_index h) {
    const std::size_t px = region(h);
    for (Mesh::Halfedge_index g : CGAL::halfedges_around_target(h, mesh)) {
      if (mesh.is_border(g) || region(g) != px) return mesh.opposite(g);
    }
    return h;
  };
  std::set<Mesh::Halfedge_index> candidates;
  for (Mesh::Halfedge_index h : mesh.halfedges()) {
    if (!mesh.is_border(h) && (mesh.is_border(mesh.opposite(h)) || region(h) != region(mesh.opposite(h))))
      candidates.insert(h);
  }
  const std::size_t limit = mesh.number_of_halfedges();
  while (!candidates.empty()) {
    Mesh::Halfedge_index start = *candidates.begin();
    for (std::size_t steps = 0; anchor(start) == kNone; ++steps) {
      start = next_border(start);
      if (steps > limit) throw std::runtime_error("a proxy boundary cycle without an anchor");
    }
    std::vector<int> polygon;
    Mesh::Halfedge_index h = start;
    std::size_t steps = 0;
    do {
      h = next_border(h);
      candidates.erase(h);
      if (anchor(h) != kNone) polygon.push_back(static_cast<int>(anchor(h)));
      if (++steps > limit) throw std::runtime_error("a proxy boundary cycle does not close");
    } while (h != start);
    out.polygons.push_back(std::move(polygon));
    out.polygon_proxy.push_back(static_cast<int>(region(start)));
  }
}

// a equals b turned by some offset (the first anchor of a cycle can differ: CGAL fixes it
// before the later cycles add their anchors).
bool same_cycle(const std::vector<int>& a, const std::vector<std::size_t>& b) {
  if (a.size() != b.size()) return false;
  if (a.empty()) return true;
  for (size_t shift = 0; shift < b.size(); ++shift) {
    bool same = true;
    for (size_t i = 0; i < a.size() && same; ++i) same = static_cast<std::size_t>(a[i]) == b[(i + shift) % b.size()];
    if (same) return true;
  }
  return false;
}

// What run_cgal_vsa and run_cgal_vsa_mesh share, timed the same way.
struct VsaPartition {
  double build_seconds = 0.0;             // TriMesh -> Surface_mesh, L21 metric
  double seed_seconds = 0.0;              // VSA object and initialize_seeds
  std::vector<double> iteration_seconds;  // one entry per run(1)
  double iterate_seconds = 0.0;           // the whole loop of run(1) calls
  int proxies = 0;                        // after seeding
  double cgal_error = 0.0;                // run(1)'s answer after the last iteration
  std::vector<std::size_t> face_proxy;    // CGAL's proxy index per face, TriMesh face order
};

// TriMesh -> Surface_mesh and the L21 metric, the VSA object and random seeding of `panels`
// proxies (std::srand(seed) first: CGAL picks with std::rand; no relaxation), `iterations` x
// run(1), and the proxy of every face; then then(mesh, vsa, proxy_of) while they still live.
template <typename Then>
void run_vsa(const ff::TriMesh& input, int panels, int iterations, unsigned seed, VsaPartition& out, Then&& then) {
  auto start = Clock::now();
  Mesh mesh;
  build_surface_mesh(input, mesh);
  const VertexPointMap vpm = get(boost::vertex_point, mesh);
  const L21Metric metric(mesh, vpm);
  out.build_seconds = seconds_since(start);

  start = Clock::now();
  Approximation vsa(mesh, vpm, metric);
  std::srand(seed);
  out.proxies =
      static_cast<int>(vsa.initialize_seeds(CGAL::parameters::seeding_method(CGAL::Surface_mesh_approximation::RANDOM)
                                                .max_number_of_proxies(static_cast<std::size_t>(panels))
                                                .number_of_relaxations(0)));
  out.seed_seconds = seconds_since(start);

  const auto iterations_start = Clock::now();
  for (int it = 0; it < iterations; ++it) {
    start = Clock::now();
    out.cgal_error = vsa.run(1);
    out.iteration_seconds.push_back(seconds_since(start));
  }
  out.iterate_seconds = seconds_since(iterations_start);

  // Not timed. extract_mesh() leaves the partition as it is: reading it before is the same.
  auto proxy_of = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  vsa.proxy_map(proxy_of);
  out.face_proxy.resize(input.triangles.size());
  for (Mesh::Face_index f : mesh.faces()) out.face_proxy[static_cast<size_t>(f)] = get(proxy_of, f);
  then(mesh, vsa, proxy_of);
}

}  // namespace

CgalVsaRun run_cgal_vsa(const ff::TriMesh& input, int panels, int iterations, unsigned seed) {
  VsaPartition part;
  run_vsa(input, panels, iterations, seed, part, [](const Mesh&, Approximation&, const auto&) {});
  CgalVsaRun out;
  out.build_seconds = part.build_seconds;
  out.seed_seconds = part.seed_seconds;
  out.iteration_seconds = part.iteration_seconds;
  out.proxies = part.proxies;
  out.cgal_error = part.cgal_error;
  out.labels.reserve(part.face_proxy.size());
  for (const std::size_t p : part.face_proxy)
    out.labels.push_back(p < static_cast<std::size_t>(out.proxies) ? static_cast<int>(p) : -1);
  return out;
}

CgalVsaMesh run_cgal_vsa_mesh(const ff::TriMesh& input, int panels, int iterations, unsigned seed,
                              double subdivision_ratio) {
  CgalVsaMesh out;
  out.subdivision_ratio = subdivision_ratio;
  VsaPartition part;
  run_vsa(input, panels, iterations, seed, part, [&](const Mesh& mesh, Approximation& vsa, const auto& proxy_of) {
    const auto start = Clock::now();
    out.manifold = vsa.extract_mesh(CGAL::parameters::subdivision_ratio(subdivision_ratio)
                                        .relative_to_chord(false)
                                        .with_dihedral_angle(false)
                                        .optimize_anchor_location(true)
                                        .pca_plane(false));
    std::vector<Point> anchor_points;
    std::vector<std::array<std::size_t, 3>> triangles;
    std::vector<std::vector<std::size_t>> cgal_polygons;
    vsa.output(CGAL::parameters::anchors(std::back_inserter(anchor_points)).triangles(std::back_inserter(triangles)));
    vsa.indexed_boundary_polygons(std::back_inserter(cgal_polygons));
    out.extract_seconds = seconds_since(start);

    // Copying into our types and naming each polygon's proxy: benchmark work, not timed.
    out.anchors.reserve(anchor_points.size());
    for (const Point& p : anchor_points) out.anchors.emplace_back(p.x(), p.y(), p.z());
    out.triangles.reserve(triangles.size());
    for (const auto& t : triangles)
      out.triangles.push_back({static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2])});

    std::vector<Mesh::Vertex_index> anchor_vertices;
    vsa.anchor_vertices(std::back_inserter(anchor_vertices));
    std::vector<std::size_t> anchor_of(mesh.number_of_vertices(), static_cast<std::size_t>(-1));
    for (std::size_t a = 0; a < anchor_vertices.size(); ++a)
      anchor_of[static_cast<std::size_t>(anchor_vertices[a])] = a;
    boundary_cycles(mesh, proxy_of, anchor_of, out);

    out.polygons_match_cgal = out.polygons.size() == cgal_polygons.size();
    for (size_t i = 0; i < out.polygons.size() && out.polygons_match_cgal; ++i)
      out.polygons_match_cgal = same_cycle(out.polygons[i], cgal_polygons[i]);
  });
  out.build_seconds = part.build_seconds;
  out.seed_seconds = part.seed_seconds;
  out.iterate_seconds = part.iterate_seconds;
  out.proxies = part.proxies;
  out.face_proxy.reserve(part.face_proxy.size());
  for (const std::size_t p : part.face_proxy) out.face_proxy.push_back(static_cast<int>(p));
  return out;
}

std::string cgal_version() { return CGAL_VERSION_STR; }

}  // namespace ff::bench
