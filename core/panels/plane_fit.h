#pragma once
// Plane fits for the panel phase, least squares in the local frame of FaceData.
#include <vector>

#include "core/cluster/face_data.h"
#include "core/mesh/topology.h"
#include "core/cluster/metric.h"
#include "core/panels/master_planes.h"
#include "core/panels/plane_relax.h"

namespace ff {

// Beyond the paper: once the combinatorics settle, fit the planes closer to the surface. The
// same least squares as plane_relax.h, with the nodes' pull towards their corners weighted
// five times less than during the rounds (node_weight 0.2), so the faces' distance to their
// plane dominates while the nodes, placed by the vertex rule, still stay near the surface.
// The layout keeps each new plane only where the panels stay valid (PanelLayout::try_planes).
// On the shared meshes this lowers the Hausdorff distance by 0-28% (bench/README.md).
//
// border (per cluster, empty for none; border_moments) and border_weight: a plane whose
// cluster runs along the input's border also fits that border, its squared distance to the
// border curve averaged and weighed border_weight times the faces' average (so the fit is
// area * (mean over faces + border_weight * mean over the border) of the squared distance).
// Why: a panel's border edge is a chord of the input's border, which it cannot follow out of
// its plane; a plane fitted to the faces alone hugs the cluster's inside and leaves the whole
// chord error at the border, where the Hausdorff distance then sits (hyperboloid_s4.off, the
// two border loops; bench/hausdorff_where.cpp). Weighing the border splits that error.
constexpr double kBorderFitWeight = 1.0;  // surface_fit_planes' border_weight in the product
std::vector<Plane> surface_fit_planes(const FaceData& faces, const std::vector<int>& labels,
                                      const MasterPlanes& masters, const std::vector<NodeConstraint>& nodes,
                                      const std::vector<ClusterMoments>& border = {}, double border_weight = 0.0);

// Per cluster: the line moments of its stretch of the input's border (area = its length, first
// and second the integrals of p and p p^T along it, exact per edge), in the frame of
// `positions` (mesh vertices, e.g. the local frame of FaceData). Zero for inside clusters.
std::vector<ClusterMoments> border_moments(const MeshTopology& topology,
                                           const std::vector<Vec3>& positions, const std::vector<int>& labels,
                                           int num_clusters);

// Per plane, the step `t` (0..1) of the way from `from` to `to`: normals blended and
// renormalised, offsets blended (a plane whose blended normal vanishes stays at `from`).
// Sizes must match.
std::vector<Plane> planes_toward(const std::vector<Plane>& from, const std::vector<Plane>& to, double t);

// The planes the panel phase starts from, per cluster: least squares of the distance to the
// cluster's faces (exact per triangle) and to its corners (the mesh vertices where it meets
// two or more other clusters or the border), the corners together weighing `corner_weight`
// times the cluster's area. Proxies fitted for clustering alone pass under curved clusters
// and their intersections stray far from the corners on near-developable surfaces (the
// paper's spikes, 2.3); a plane that also passes near its corners meets its neighbours near
// them. `orientation` gives each normal's side.
std::vector<Plane> corner_fit_planes(const std::vector<ClusterMoments>& moments,
                                     const std::vector<std::vector<Vec3>>& corners,
                                     const std::vector<Vec3>& orientation, double corner_weight);

}  // namespace ff
