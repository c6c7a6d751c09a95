// The Session's NURBS path (session.h, load_surfaces): surfaces from a Rhino file tessellated
// by the core at one edge length for the whole set, joined with the file's meshes, then loaded
// like any mesh (clean-up with the set's weld tolerance, so shared edges join).
#include <cmath>
#include <string>
#include <vector>

#include "core/prepare/nurbs_json.h"
#include "core/prepare/nurbs_tessellate.h"
#include "core/util/error.h"
#include "core/util/json_writer.h"
#include "wasm/guarded.h"
#include "wasm/mesh_arrays.h"
#include "wasm/session.h"

namespace ff::wasm {

namespace {

constexpr long long kMaxTessellatedTriangles = 4'000'000;

struct SurfaceStats {
  std::string name;
  int triangles = 0, samples_u = 0, samples_v = 0, seam_welded = 0;
};

}  // namespace

std::string Session::load_surfaces(const std::string& name, const std::string& surfaces_json,
                                   const std::vector<double>& positions, const std::vector<std::uint32_t>& indices) {
  return guarded([&] {
    SurfaceSet set;
    try {
      set = surface_set_from_json(surfaces_json);
    } catch (const InputError& e) {
      throw InputError(name + ": " + e.what());
    }
    // The triangle soup beside the surfaces, checked like Session::load_arrays.
    TriMesh soup = mesh_from_arrays(name + ": mesh ", positions, indices);
    if (set.surfaces.empty() && soup.triangles.empty())
      throw InputError(name + ": no surfaces and no triangles to load");
    double edge = set.edge_length;
    if (!set.surfaces.empty() && !(edge > 0.0)) {
      // One edge length for every surface, so neighbours come out alike: the triangle budget
      // spread over their total area (a grid of squares split in two).
      double area = 0.0;
      for (const NamedSurface& s : set.surfaces) area += nurbs_area_estimate(s.surface);
      if (!(area > 0.0) || !std::isfinite(area)) throw InputError(name + ": the surfaces have no area");
      edge = std::sqrt(2.0 * area / set.target_triangles);
    }
    std::vector<SurfaceStats> stats;
    for (const NamedSurface& s : set.surfaces) {
      TessellationOptions options;
      options.edge_length = edge;
      options.max_triangles = kMaxTessellatedTriangles - static_cast<long long>(soup.triangles.size());
      const SurfaceTessellation t = tessellate_nurbs(s.surface, options, s.name);
      const int base = soup.num_vertices();
      soup.positions.insert(soup.positions.end(), t.mesh.positions.begin(), t.mesh.positions.end());
      for (const Triangle& tri : t.mesh.triangles)
        soup.triangles.push_back({tri[0] + base, tri[1] + base, tri[2] + base});
      stats.push_back({s.name, t.mesh.num_faces(), t.samples_u, t.samples_v, t.seam_vertices_welded});
    }
    CleanOptions clean;
    clean.weld_tolerance = set.weld_tolerance;
    const int input_triangles = soup.num_faces();
    std::string info = load(name, std::move(soup), input_triangles, clean);
    // MeshInfo plus what the tessellation did: spliced in before the closing brace.
    JsonWriter j;
    j.begin_object().value("edgeLength", edge).begin_array("surfaces");
    for (const SurfaceStats& s : stats) {
      j.begin_object(nullptr).value("name", s.name).value("triangles", s.triangles);
      j.value("samplesU", s.samples_u).value("samplesV", s.samples_v).value("seamWelded", s.seam_welded).end_object();
    }
    j.end_array().end_object();
    while (!info.empty() && info.back() != '}') info.pop_back();  // the writer ends with a newline
    info.pop_back();
    info += "," + j.str().substr(1);
    return info;
  });
}

}  // namespace ff::wasm
