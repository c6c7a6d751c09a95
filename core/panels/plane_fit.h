#pragma once
// Plane fits for the panel phase, least squares in the local frame of FaceData.
#include <vector>

#include "core/cluster/face_data.h"
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
std::vector<Plane> surface_fit_planes(const FaceData& faces, const std::vector<int>& labels,
                                      const MasterPlanes& masters, const std::vector<NodeConstraint>& nodes);

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
