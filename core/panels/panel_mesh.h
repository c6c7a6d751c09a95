#pragma once
// PanelMesh: the planar polygonal remeshing, the product's main result. Every panel lies in
// its plane by construction (its vertices are intersections of the planes around them), so
// planarity is exact up to floating point. Coordinates are world coordinates.
#include <cstdint>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff {

// What is wrong with one panel; all false/zero for a valid panel.
struct PanelIssues {
  bool not_simple = false;        // its polygon self-intersects in its own plane
  bool flipped = false;           // some edge runs against the cluster's orientation (paper fig. 6)
  bool not_star = false;          // empty kernel (paper fig. 7e)
  int spike_vertices = 0;         // vertices farther than 0.2 D from their mesh corner (paper 2.3)
  bool too_few_vertices = false;  // fewer than 3 vertices
  bool not_disk = false;          // its cluster has a hole, is enclosed, pinches or touches a neighbour twice
  bool acute_corner = false;      // a corner below the designer's minimum angle (glass mode, DESIGN.md 3)
  // Covers under kMinCoveredShare of its faces' area (panel_check.h). Not a validity check
  // (the paper's pass it): the panel rounds move such a cluster elsewhere while they can.
  bool collapsed = false;

  bool valid() const {
    return !not_simple && !flipped && !not_star && spike_vertices == 0 && !too_few_vertices && !not_disk &&
           !acute_corner;
  }
};

struct PanelMesh {
  std::vector<Vec3> vertices;            // world coordinates
  std::vector<std::vector<int>> panels;  // vertex indices, counter-clockwise seen from the
                                         // side the input surface's normals point to
  // Per panel: its plane n.x = offset (unit n, oriented like the input surface), the
  // cluster it came from, and its issues.
  std::vector<Vec3> plane_normals;
  std::vector<double> plane_offsets;
  std::vector<int> panel_cluster;
  // Per panel: the panel it was cut from by the glass split (glass_split.h), in the numbering
  // before the split; empty when nothing was split (each panel is its own source).
  std::vector<int> panel_source;
  std::vector<PanelIssues> issues;
  // Per vertex: the mesh vertex (corner) it was placed for, and how many distinct planes
  // define it (3: a node, 2: on a boundary or a coplanar seam, 1: an extra border vertex).
  std::vector<int> vertex_corner;
  std::vector<int> vertex_planes;
  // Per vertex: where it belongs (its mesh corner, or the middle of the short chain between
  // the two corners of its node group); a vertex farther than spike_distance from it is a spike.
  std::vector<Vec3> vertex_reference;
  double spike_distance = 0.0;
  // The world point the panels were solved about (FaceData::origin, the middle of the whole
  // mesh): their vertices carry the rounding of coordinates that far from it as well, which
  // matters when a far-off part puts it far from a panel (quality/planarity.h).
  Vec3 solve_origin = Vec3::Zero();
  // Per vertex, when not empty: its own spike distance (the vertices of a locked panel keep
  // the one they were locked with, LayoutOptions::locked_spike_distance).
  std::vector<double> vertex_spike_distance;
  // Per input triangle (of the cleaned mesh): the panel it belongs to, -1 for the faces of an
  // unbuilt cluster.
  std::vector<int> face_panel;
  // Clusters that could not become a panel at all (not a disk, fewer than 3 vertices): their
  // faces are left uncovered, so these count as invalid panels and break the topology.
  std::vector<int> unbuilt_clusters;

  int num_panels() const { return static_cast<int>(panels.size()); }
  int num_invalid() const {
    int count = 0;
    for (const PanelIssues& i : issues) count += i.valid() ? 0 : 1;
    return count + static_cast<int>(unbuilt_clusters.size());
  }
};

}  // namespace ff
