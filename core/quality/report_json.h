#pragma once
// The quality report as JSON fields (DESIGN.md 4 keys), shared by `flatfacet remesh --report`
// and the browser's report, so both name and judge things the same way.
#include <string>
#include <vector>

#include "core/panels/panel_mesh.h"
#include "core/quality/planarity.h"
#include "core/quality/report.h"
#include "core/util/json_writer.h"

namespace ff {

// Exit 0 material: a non-empty panel mesh in which neither the panel phase's own validation
// nor the independent quality measurement finds an invalid panel.
bool all_panels_valid(const PanelMesh& panels, const QualityReport& quality);

// Exit 0 material as a whole: every panel valid and the input's topology kept (DESIGN.md 5).
bool result_valid(const PanelMesh& panels, const QualityReport& quality);

// "valid", "some panels invalid", "topology changed" (every panel valid, but not the input's
// Euler characteristic and boundary loops) or "no panels".
const char* panels_status(const PanelMesh& panels, const QualityReport& quality);

// "" when the topology is kept; else what changed, for a person: "the panels do not keep the
// surface's topology (Euler characteristic 1 -> 2, boundary loops 1 -> 0)".
std::string topology_phrase(const QualityReport& quality);

// The names of a panel's problems as they appear in the report ("spike", "flipped", ...).
std::vector<std::string> panel_problems(const PanelIssues& issues);

// Writes into the open object: max_planarity, hausdorff (and both halves, worst point),
// topology, flips, kernels, spikes, invalid_panels, interior_valence, valence3_share,
// min_corner_angle_deg.
void write_quality_fields(JsonWriter& j, const QualityReport& quality);

// One invalid panel as the report lists it. panel -1: a cluster left unbuilt (no outline: not
// a disk, too few corners), whose one problem is "unbuilt".
struct InvalidPanel {
  int panel = -1;
  int cluster = -1;
  std::vector<std::string> problems;  // panel_problems' names; "quality_check" when only the
                                      // independent measurement found it invalid
  int vertices = 0;
  int spike_vertices = 0;
};

// Every invalid panel, so nothing is hidden (DESIGN.md 3): the panels the quality measurement
// found invalid plus any the panel phase flagged itself, in increasing order, then the
// unbuilt clusters.
std::vector<InvalidPanel> list_invalid_panels(const PanelMesh& panels, const QualityReport& quality);

// Writes "invalid": list_invalid_panels as objects (panel, cluster, problems, vertices, and
// spike_vertices where there are any).
void write_invalid_panels(JsonWriter& j, const PanelMesh& panels, const QualityReport& quality);

// The invalid panels in a few words for a person, "3 panels invalid (not_star 2, unbuilt 1)":
// each problem with the number of panels that have it, in panel_problems' order, then
// "off_plane", "quality_check" and "unbuilt"; "" when none is invalid.
std::string invalid_panels_phrase(const PanelMesh& panels, const QualityReport& quality);

// "" when the panels are flat to kPlanarityTarget; else a sentence for a person saying how
// flat they are and, when the coordinates' own rounding explains it, what would make them flat:
// moving the model near the origin (planarity_floor), or removing a far-off part that put the
// middle of the mesh, about which the panels are solved, far from them (planarity_floor_solve).
std::string planarity_phrase(const QualityReport& quality);

// Panels that pass through each other (QualityReport::crossing_pairs), as one clause naming
// the first pairs (labels P1.. as in the parts list) and the deepest; empty when none.
std::string crossing_phrase(const QualityReport& quality);

}  // namespace ff
