#pragma once
// What `flatfacet remesh` writes besides the panels: the report JSON (DESIGN.md 4 keys and
// more), the OBJ's comment lines and the one-line stdout summary. Pure formatting of a
// finished run, so the command itself stays about arguments, stages and files.
#include <string>
#include <vector>

#include "cli/input.h"
#include "core/panels/panel_mesh.h"
#include "core/prepare/prepare.h"
#include "core/quality/report.h"
#include "core/remesher.h"

namespace ff::cli {

struct RemeshTimings {
  double prepare = 0.0;  // read + clean + resolution (prepare.h) + topology and face data
  double cluster = 0.0;  // seeding + Lloyd phase
  double panels = 0.0;   // panel rounds + plane optimisation
  double quality = 0.0;  // measuring the result
  double total = 0.0;
};

struct RemeshRun {
  const LoadedInput& input;
  const Remesher& remesher;
  const QualityReport& quality;
  int requested_panels = 0;
  std::string seeding;  // "farthest" or "random", as given
  RemeshTimings timings;
  const PrepareReport& prepare;
};

std::string remesh_report_json(const RemeshRun& run);
// Comment lines for the panels OBJ: tool, input, panel count; nothing that varies between
// identical runs (so identical runs give identical bytes).
std::string panels_obj_comment(const RemeshRun& run);
// One line for stdout when neither --out nor --report is given.
std::string remesh_summary_line(const RemeshRun& run);

}  // namespace ff::cli
