#pragma once
// PanelLayout: one attempt at the panels of a clustering (paper 2.1-2.5). For every node
// group (corner_groups.h) it picks a pairing (node_split.h), places each node by the vertex
// rule on the master planes, walks each cluster's boundary loop into a polygon (border
// stretches get extra vertices so boundary panels keep their area, paper 2.5), and checks
// each panel in its own plane: simple, oriented like its cluster, star-shaped, no spike
// (paper 2.2-2.3). The fixes that need no reclustering live here too: switching pairings
// (fig. 6) and tilting the planes of spikes (2.3). Everything is in the local frame of
// FaceData.
#include <array>
#include <vector>

#include "core/cluster/face_data.h"
#include "core/mesh/topology.h"
#include "core/panels/corner_groups.h"
#include "core/panels/master_planes.h"
#include "core/panels/node_split.h"
#include "core/panels/panel_graph.h"
#include "core/panels/panel_mesh.h"
#include "core/panels/plane_relax.h"

namespace ff {

struct LayoutOptions {
  double diameter = 1.0;              // D = sqrt(area / n), the metric's length unit (local frame)
  double spike_distance = 0.2;        // a vertex farther than this from where it belongs is a spike
  double border_tolerance = 0.02;     // extra border vertices until the border is this * D close
  double tolerance = 1e-9;            // lengths below this count as zero in the panel checks
  double min_corner_angle_deg = 0.0;  // a convex corner below this is a problem; 0 = off
  bool glass = false;                 // judge the corners of the convex pieces (glass_split.h)
  // Cluster triples (sorted, kBoundary first) that must be nodes where a group can have them:
  // the corners of locked panels (remesher_edits.cpp), so their outlines stay. A group with
  // any keeps the pairing that has them all (none: as usual) and is never switched.
  std::vector<std::array<int, 3>> held_nodes;
  // Cluster sets (sorted) of node groups a lock holds as one point: a group of exactly these
  // clusters is laid out as one vertex, where its planes meet (they are held through it).
  std::vector<std::vector<int>> held_single;
  // Corners a lock holds grouped as they were (corner_groups.h).
  HeldGrouping held_grouping;
  // Per cluster (empty for none): the spike distance a locked panel was locked with (0 for a
  // cluster not locked). Its vertices keep being judged by it (the larger of it and
  // spike_distance), in every panel they are on: the outline is kept exactly, while the
  // distance follows the panel count (remesher_edits.cpp).
  std::vector<double> locked_spike_distance;
  // Per cluster (empty for none): the diameter D a locked panel was laid out with (0: not
  // locked): its border runs are thinned with it, so it keeps the same border vertices.
  std::vector<double> locked_diameter;
};

// What a lock holds of a panel's corners (PanelLayout::corner_nodes).
struct CornerNodes {
  std::vector<std::array<int, 3>> nodes;         // each node's clusters, sorted
  std::vector<std::vector<int>> single_groups;   // each group made one point: its clusters, sorted
  std::vector<std::vector<int>> group_vertices;  // each node group: the mesh vertices of its corners
};

// A panel's polygon: its vertices (local frame) in counter-clockwise order.
struct PanelPolygon {
  std::vector<Vec3> points;
  std::vector<int> node;        // per vertex: node id, or -1 for an extra border vertex
  std::vector<int> corner;      // per vertex: a mesh vertex it stands for
  std::vector<Vec3> reference;  // per vertex: where it belongs (its spike test)
};

class PanelLayout {
 public:
  // positions: mesh vertex positions in the local frame. The references must outlive the layout.
  // forced: corner pairs to treat as one node group (group_corners).
  // build_panels false: the panels are left unbuilt until the first set_planes(), which builds
  // them all (for a caller that sets new planes right away, as the relaxation does: the
  // panels come out the same, each built once); until then only planes(), node_constraints()
  // and spike_nodes() may be read.
  PanelLayout(const TriMesh& mesh, const MeshTopology& topology, const std::vector<int>& labels,
              const std::vector<Vec3>& positions, const PanelGraph& graph, MasterPlanes planes,
              const LayoutOptions& options, const std::vector<std::pair<int, int>>& forced = {},
              bool build_panels = true);

  int num_clusters() const { return static_cast<int>(polygons_.size()); }
  const std::vector<PanelIssues>& issues() const { return issues_; }
  int num_invalid() const;
  // What a change to the planes, nodes or pairings must not make worse (beyond the paper):
  // invalid panels, and among the valid ones collapsed panels (PanelIssues::collapsed), a
  // sliver over its neighbours' faces that the paper's checks let through.
  struct Faults {
    int invalid = 0;
    int collapsed = 0;
    bool no_worse_than(const Faults& before) const {
      return invalid <= before.invalid && collapsed <= before.collapsed;
    }
  };
  Faults faults() const;  // over all panels
  const MasterPlanes& planes() const { return planes_; }
  const PanelPolygon& polygon(int cluster) const { return polygons_[static_cast<size_t>(cluster)]; }
  // The clusters of a node (PanelPolygon::node), sorted (kBoundary first when there).
  std::array<int, 3> node_clusters(int node) const;
  // The clusters of every node at the corners of the panel of `cluster`, each node as its
  // own: where a group's nodes meet in one point, its outline shows the group's first node,
  // which may not be one of this panel's (node_clusters of PanelPolygon::node would name a
  // cluster across the point); and the clusters of the groups there made one point.
  CornerNodes corner_nodes(int cluster) const;
  // The mesh vertices where the panel of `cluster` has a problem (spikes, or every corner of
  // a panel that is flipped or not star-shaped): where a split should seed.
  std::vector<int> problem_corners(int cluster) const;

  // Tries the other pairings of node groups next to invalid panels; keeps a change when it
  // lowers the number of invalid panels around the group. Returns the number of changes.
  int switch_pairings();
  // Tilts the planes around spike nodes towards their corner (paper 2.3); keeps the tilts
  // when they lower the number of invalid panels; fixed_masters (per master, empty for none)
  // stay, hinged ones (per master, empty for none) tilt only about their hinge's line.
  // Returns true when it kept any.
  bool tilt_spike_planes(const std::vector<char>& fixed_masters = {}, const std::vector<PlaneHinge>& hinges = {});
  // Where an invalid panel has a corner at an interior group of four or more distinct
  // planes (whose nodes came out in an order no pairing mends, e.g. a flipped short edge),
  // moves those planes (by translation; fixed_masters, per master, empty for none: at most
  // one of them stays, and the point is on it) through their least-squares point near the
  // group and makes the group one vertex, as make_single_point_nodes() does. Kept only when
  // fewer panels are invalid. Returns the number of groups made single.
  int single_point_fix(const std::vector<char>& fixed_masters = {});
  // At the nodes of invalid panels on three distinct planes (farthest from their corner
  // first): turns one of the node's planes (by at most max_turn_deg, about its centre or else
  // about a near-spike node on it, which stays) so the node comes to within half the spike
  // distance of its corner, or onto the other two planes' line nearest it; each turn kept
  // only when fewer panels around the plane are invalid (aim_node_planes.cpp). fixed_masters
  // (per master, empty for none) and single-point masters stay. Returns the turns kept.
  int aim_node_planes(const std::vector<char>& fixed_masters = {}, double max_turn_deg = 5.0);
  // At each edge of a flipped or not-simple panel (plane P) between two three-plane nodes on
  // a shared neighbour plane Q (their other planes A and B): turns Q (by at most
  // max_turn_deg, and only while it stays within half the spike distance of its centre) so
  // its trace passes through chosen spots, each node kept or put just before or after the
  // point P, A and B share, which sets the two nodes' order along the edge; the smallest
  // turns first, each kept only when fewer panels around Q are invalid (aim_edge_order.cpp).
  // fixed_masters (per master, empty for none) and single-point masters stay. Returns the
  // turns kept.
  int aim_edge_order(const std::vector<char>& fixed_masters = {}, double max_turn_deg = 30.0);
  // At each invalid panel whose plane faces away from its faces (the sum of their area
  // normals; build_panel() flags it flipped): turns the plane about its centre toward that
  // normal until it is 80, 60, 30 or 0 degrees from it, or mirrors it across the plane normal
  // to it; the turn leaving the fewest panels around it invalid kept when that is fewer
  // (aim_face_normals.cpp). fixed_masters (per master, empty for none) and
  // single-point masters stay. Returns the turns kept.
  int aim_face_normals(const std::vector<char>& fixed_masters = {});
  // At node groups of four or more clusters (not held, not single) where a corner at or next
  // to one of the group's nodes is below below_deg: tries the group's other pairings and
  // keeps the one whose smallest such corner is widest, as long as no more panels around it
  // are invalid or collapsed; where still below, makes the group one vertex (make_group_single)
  // when that widens it and narrows, invalidates and collapses nothing more of what its planes
  // reach (widen_needle_corners.cpp).
  // fixed_clusters (per cluster, empty for none): their planes stay (locked panels), so no
  // group on one of their masters is made one vertex. Returns the number of groups changed.
  int widen_needle_corners(double below_deg, const std::vector<char>& fixed_clusters = {});
  // The masters whose planes pass through the point of a single-point group, sorted.
  std::vector<int> single_point_masters() const;
  // Replaces the plane of each master with `candidates[m]`, one at a time, keeping each
  // change that adds neither invalid nor collapsed panels around it (beyond the paper: planes
  // fitted to the surface). Returns how many it kept.
  // Masters pinned through a single point (single_point_fix) keep their planes.
  // passes: up to this many passes over the masters, another only after one kept any (a
  // plane refused while its neighbours were elsewhere may pass once they moved); a plane is
  // tried again only when a panel it reaches changed since it was refused. Returns the total.
  int try_planes(const std::vector<Plane>& candidates, int passes = 1);

  // Every node's reference point and master planes (for plane_relax.h), new planes for all
  // masters, and which nodes are spikes (too far, or planes without a common point).
  std::vector<NodeConstraint> node_constraints() const;
  void set_planes(std::vector<Plane> planes);
  std::vector<char> spike_nodes() const;
  // The clusters at spike nodes (of two or more distinct planes) that share their master with
  // other clusters (per cluster): alone, their planes can tilt where a master could not.
  std::vector<char> spike_master_clusters() const;
  // Chains of invalid panels whose two nodes came out in the opposite order to their corners
  // (a flipped edge, paper fig. 6), as sorted corner pairs: grouping them lets the pairing
  // switch which two clusters share the edge.
  std::vector<std::pair<int, int>> reversed_chains() const;

  // Single-point nodes (paper 2.2, the designer's alternative to splitting): where four or
  // more distinct planes meet at an interior node group, move those planes so they all pass
  // through one point (their least-squares point) and make the group one vertex. A plane can
  // be made to pass through two such points (a translation, then a rotation about the first);
  // a group that would need a third on some plane stays split, as does one whose change
  // makes a panel around it invalid. Exact: the vertex lies on every plane by construction.
  // Returns the number of groups made single. Planes of `fixed_clusters` (per cluster; empty:
  // none), a locked panel's and its neighbours', stay as they are, and so do the groups whose
  // pairing a lock holds.
  int make_single_point_nodes(const std::vector<char>& fixed_clusters = {});

  // From now on a panel whose plane faces away from its faces (the sum of their area
  // normals) is flipped too, as the quality report (core/quality/report.cpp) calls it
  // misoriented although its outline may run counter-clockwise in its own plane (a plane
  // turned across its faces); rebuilds every panel. The panel rounds leave it off while
  // panels are invalid, so their choices stay as they were; the remesher turns it on for a
  // round that looks valid (Remesher::panel_round: a misoriented panel then keeps the rounds
  // going) and for the attempts it finishes with (Remesher::finish_panels), before the mend.
  void judge_orientation();
  // From now on a corner below `deg` (0: none) is a panel problem (acute_corner), as
  // LayoutOptions::min_corner_angle_deg makes it; rebuilds every panel. Setting it back
  // gives exactly the panels before.
  void judge_min_corner_angle(double deg);
  // The smallest corner (degrees, in its panel's plane) of every panel (360 when none).
  double smallest_corner_deg() const;

  PanelMesh to_panel_mesh(const FaceData& frame) const;

 private:
  void place_group_nodes(int group);
  double pairing_cost(int group) const;
  void build_panel(int cluster);
  void rebuild(const std::vector<int>& clusters);
  void rebuild_all();
  // After planes_ changed from `old`; all_panels: every panel built, not only those changed.
  void rebuild_changed(const std::vector<Plane>& old, bool all_panels = false);
  std::vector<int> clusters_of_group(int group) const;
  // The smallest interior angle (degrees) of these panels at the group's nodes and at the
  // vertices next to them (360 when there is none).
  double smallest_corner_near_group(int group, const std::vector<int>& clusters) const;
  std::vector<int> distinct_masters(int group) const;  // the masters of its clusters, in their order
  // Group g (interior, four or more distinct masters, none of them through another group's
  // point, not held) made one vertex: its masters translated through their least-squares
  // point, which must be within the spike distance of the group's reference; nodes and
  // panels rebuilt. `old` gets the planes before. False (nothing changed) when it cannot be.
  bool make_group_single(int g, std::vector<Plane>& old);
  // Back to the planes `old` and the split group, exactly as before make_group_single().
  void undo_group_single(int g, const std::vector<Plane>& old);
  // The smallest interior angle (degrees) of these panels' corners (360 when none).
  double smallest_corner(const std::vector<int>& clusters) const;
  // The same over the corners `take(polygon, before, at, after)` (vertex indices) accepts.
  template <typename Take>
  double smallest_corner_among(const std::vector<int>& clusters, Take take) const;
  std::vector<int> masters_of_node(size_t node) const;
  // The groups a master's plane places and the panels they (and its own) build, sorted.
  void master_reach(int master, std::vector<int>& groups, std::vector<int>& clusters) const;
  // How many of these clusters' panels are invalid; their Faults.
  int invalid_among(const std::vector<int>& clusters) const;
  Faults faults_among(const std::vector<int>& clusters) const;
  // Master m gets `plane`: its groups' nodes placed again, its reach's panels rebuilt
  // (groups, clusters: from master_reach).
  void set_master_plane(int m, const Plane& plane, const std::vector<int>& groups, const std::vector<int>& clusters);
  // set_master_plane, kept when fewer of the clusters' panels are invalid than before, else
  // the old plane put back (nodes and panels are functions of the planes: exactly as they
  // were). Returns whether it was kept.
  bool try_master_plane(int m, const Plane& plane, const std::vector<int>& groups, const std::vector<int>& clusters);
  // A node's distinct master planes, sorted (at most three: one per cluster of its triangle).
  struct NodeMasters {
    int m[3] = {-1, -1, -1};
    int count = 0;
    bool operator==(const NodeMasters& o) const {
      return count == o.count && m[0] == o.m[0] && m[1] == o.m[1] && m[2] == o.m[2];
    }
  };
  NodeMasters node_masters(size_t node) const;
  bool touches_boundary(int group, int node) const;

  const TriMesh& mesh_;
  const MeshTopology& topology_;
  const std::vector<int>& labels_;
  const std::vector<Vec3>& positions_;
  const PanelGraph& graph_;
  MasterPlanes planes_;
  LayoutOptions options_;
  NodeGroups groups_;

  std::vector<Pairing> pairing_;  // per group
  std::vector<char> held_group_;  // per group: its pairing holds LayoutOptions::held_nodes
  std::vector<int> node_offset_;  // per group, into the node arrays
  std::vector<Vec3> node_point_;  // per node
  std::vector<int> node_planes_;  // distinct planes defining it
  std::vector<char> node_exact_;  // false: its planes have no common point (a spike)
  // Per node, only with LayoutOptions::locked_spike_distance: how far it may be from its
  // reference; and the same for a vertex of a cluster's polygon (node or border vertex).
  std::vector<double> node_limit_;
  double spike_limit(const PanelPolygon& poly, size_t i, int cluster) const;
  std::vector<int> node_group_;
  // Per node: the first node of its group on the same planes (itself if none). Such nodes are
  // one point (e.g. where coplanar clusters meet), so they are one vertex.
  std::vector<int> node_alias_;
  // Per group: whether it is one vertex where all its planes meet, and that point.
  std::vector<char> single_;
  std::vector<Vec3> single_point_;
  std::vector<std::vector<int>> groups_of_cluster_;
  // Per mesh vertex: on a boundary loop that meets fewer than three node groups (a small hole
  // between two panels). Each panel thins its own border runs, so both could drop every border
  // vertex of such a loop and close the hole; their runs along it keep at least one.
  std::vector<char> on_short_loop_;
  std::vector<PanelPolygon> polygons_;
  std::vector<PanelIssues> issues_;
  // Per cluster: the sum of its faces' area normals. A panel facing away from it is
  // misoriented (the quality check's test, core/quality/report.cpp), even when its outline
  // runs counter-clockwise in its own plane (a plane turned across its faces).
  std::vector<Vec3> faces_normal_;
  bool judge_orientation_ = false;  // judge_orientation()
  bool built_ = true;               // false: the panels wait for set_planes() (build_panels)
  // build_panel()'s working memory, kept between calls (it runs thousands of times a round).
  std::vector<int> scratch_triangles_, scratch_border_;
  struct ScratchEvent {
    int group, vertex, border, border_end;
  };
  std::vector<ScratchEvent> scratch_events_;
  std::vector<NodeMasters> scratch_masters_;  // place_group_nodes()
  std::vector<Plane> scratch_planes_;
};

}  // namespace ff
