// The Session's density field (session.h): one value per vertex of the cleaned mesh, the
// field the page paints. It lives in params_.density, so set_params keeps it and a new
// Remesher starts with it; a change warm-starts a solve like a parameter change does.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "core/density/density_field.h"
#include "core/util/error.h"
#include "wasm/guarded.h"
#include "wasm/session.h"

namespace ff::wasm {

std::string Session::set_density(const std::vector<double>& density) {
  return guarded([&] {
    if (!density.empty()) {
      if (mesh_.num_vertices() == 0) throw InputError("density: no mesh loaded");
      if (density.size() != static_cast<size_t>(mesh_.num_vertices())) {
        throw InputError("density has " + std::to_string(density.size()) + " values; the mesh has " +
                         std::to_string(mesh_.num_vertices()) + " vertices (painted on another mesh? clear the paint)");
      }
      for (size_t i = 0; i < density.size(); ++i) {
        if (!std::isfinite(density[i]) || density[i] <= 0.0) {
          throw InputError("density value " + std::to_string(i + 1) + " is " + std::to_string(density[i]) +
                           "; densities must be finite and greater than 0");
        }
      }
    }
    forget_mesh_before();  // accepted: designing on this mesh has begun
    // The same field again changes nothing (the worker sends it before every solve).
    if (density == params_.density) return status_json(true, "");
    RemeshParams params = params_;
    params.density = density;
    if (remesher_) {
      const bool mid_solve = !remesher_->done();
      remesher_->set_params(params);  // throws and keeps everything on a bad field
      if (mid_solve)
        quality_.reset();
      else
        forget_result();
    }
    params_ = std::move(params);
    return status_json(true, "");
  });
}

// The page's colour map of the effective density (expression x paint) needs the expression's
// values; they depend on curvature and the bounding box, which only the core computes.
std::vector<double> Session::expression_density(const std::string& expression) const {
  if (expression.empty() || mesh_.num_vertices() == 0) return {};
  try {
    const Expression parsed = Expression::parse(expression);
    const MeshTopology topology = build_topology(mesh_);
    std::optional<VertexCurvature> curvature;
    if (parsed.uses_curvature()) curvature = vertex_curvature(mesh_, topology);
    return ff::expression_density(mesh_, topology, parsed, curvature ? &*curvature : nullptr);
  } catch (const InputError&) {
    return {};  // the solve reports it
  }
}

}  // namespace ff::wasm
