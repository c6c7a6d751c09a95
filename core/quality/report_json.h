#pragma once
// The quality report as JSON fields (DESIGN.md 4 keys), shared by `flatfacet remesh --report`
// and the browser's report, so both name and judge things the same way.
#include <string>
#include <vector>

#include "core/panels/panel_mesh.h"
#include "core/quality/report.h"
#include "core/util/json_writer.h"

namespace ff {

// Exit 0 material: a non-empty panel mesh in which neither the panel phase's own validation
// nor the independent quality measurement finds an invalid panel.
bool all_panels_valid(const PanelMesh& panels, const QualityReport& quality);

// "valid", "some panels invalid" or "no panels".
const char* panels_status(const PanelMesh& panels, const QualityReport& quality);

// The names of a panel's problems as they appear in the report ("spike", "flipped", ...).
std::vector<std::string> panel_problems(const PanelIssues& issues);

// Writes into the open object: max_planarity, hausdorff (and both halves, worst point),
// topology, flips, kernels, spikes, invalid_panels, interior_valence, valence3_share,
// min_corner_angle_deg.
void write_quality_fields(JsonWriter& j, const QualityReport& quality);

// Writes "invalid": per invalid panel its id, cluster, problems and vertex count, so nothing
// is hidden (DESIGN.md 3): the panels the quality measurement found invalid plus any the
// panel phase flagged itself, in increasing order.
void write_invalid_panels(JsonWriter& j, const PanelMesh& panels, const QualityReport& quality);

}  // namespace ff
