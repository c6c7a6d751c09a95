#pragma once
// Beyond the paper: once the combinatorics settle, fit each master plane to the surface it
// stands for (least squares of the surface's distance to the plane, exact per triangle over
// the faces of its clusters), so the panels hug the design closer at the same panel count
// than proxies fitted for the clustering metric. The layout keeps a new plane only where
// the panels stay valid (PanelLayout::try_planes).
#include <vector>

#include "core/cluster/face_data.h"
#include "core/cluster/metric.h"
#include "core/panels/master_planes.h"

namespace ff {

std::vector<Plane> surface_fit_planes(const FaceData& faces, const std::vector<int>& labels,
                                      const MasterPlanes& masters);

// The planes the panel phase starts from, per cluster: least squares of the distance to the
// cluster's faces (exact per triangle) and to its corners (the mesh vertices where it meets
// two or more other clusters or the border), the corners together weighing `corner_weight`
// times the cluster's area. Proxies fitted for clustering alone pass under curved clusters
// and their intersections stray far from the corners on near-developable surfaces (the
// paper's spikes, 2.3); a plane that also passes near its corners meets its neighbours near
// them. `orientation` gives each normal's side. Local frame.
std::vector<Plane> corner_fit_planes(const std::vector<ClusterMoments>& moments,
                                     const std::vector<std::vector<Vec3>>& corners,
                                     const std::vector<Vec3>& orientation, double corner_weight);

}  // namespace ff
