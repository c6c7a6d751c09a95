#pragma once
// CGAL VSA's output (cgal_vsa.h) as ff::PanelMesh, so that measure_quality scores it with the
// same code as ours: its anchor polygons as panels, and its indexed triangles as panels.
#include "bench/cgal_vsa.h"
#include "core/panels/panel_mesh.h"

namespace ff::bench {

// CGAL's anchor polygons as a PanelMesh: one panel per polygon, its plane through the
// polygon's vertex centroid with the Newell normal (CGAL's polygons are not planar, which
// is what max_planarity shows). No mesh corners (vertex_corner -1: no spike check), no
// issues of its own; face_panel maps a proxy's faces to its panel when it has exactly one.
PanelMesh polygon_panels(const CgalVsaMesh& m, int faces);

// CGAL's actual output, its indexed triangles over the anchors, as one panel per triangle:
// for its Hausdorff distance and topology next to the polygons'.
PanelMesh triangle_panels(const CgalVsaMesh& m);

}  // namespace ff::bench
