#pragma once
// Preparation: the mesh the clustering sees, at a resolution that suits the panel count
// (DESIGN.md 2; paper 3.1 and 5: 20-100 triangles per panel, and the longest edge bounds how
// well a panel outline can follow its planes).
//
// Policy (automatic mode):
// - fewer than 30 triangles per panel: isotropic remeshing (isotropic_remesh.h) to the edge
//   length whose equilateral triangles give about 50 per panel. Below 20 always (the least
//   the panel phase works with; refused when even 20 would exceed kPrepareMaxTriangles); from
//   20 to 30 when 50 per panel fits under that cap, else the mesh stays as it is. Measured
//   (bench/README.md, "Preparation below 30 triangles per panel"): face.obj (51,712
//   triangles) as it is ended with invalid panels at 5 of 6 runs at 1,846-2,248 panels
//   after all retries, in 54-93 s; refined, 6 of 6 valid in 2.5-4.1 s. A refinement runs 5
//   remeshing rounds (half the time of pmp's 10, as valid and as close: prepare.cpp);
// - more than 1000 triangles per panel AND more than 400,000 triangles: remeshing to about
//   100 per panel (the paper's upper end: a huge mesh costs time and memory and buys nothing
//   the panels can show, while keeping twice the refinement target keeps the fidelity);
// - otherwise the mesh is used as it is, bit for bit.
// With a non-uniform density the count that decides is the one in the dense panels: the
// triangles per panel divided by the area-weighted 90th percentile of density / mean density.
// An explicit edge length always remeshes to it. Every decision is one sentence in the report,
// and a remeshed surface's distance to the input (sampled both ways) is measured and reported.
#include <string>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace ff {

// Policy numbers, public so callers and tests name them rather than repeat them.
constexpr int kPrepareTargetTrianglesPerPanel = 50;
constexpr int kPrepareMinTrianglesPerPanel = 20;     // below: always refined (or refused)
constexpr int kPrepareRefineTrianglesPerPanel = 30;  // below: refined when 50 each fit the cap
constexpr int kPrepareCoarsenTrianglesPerPanel = 100;
constexpr int kPrepareHugeTrianglesPerPanel = 1000;
constexpr int kPrepareHugeTriangles = 400000;  // PrepareOptions::huge_triangles' default
constexpr int kPrepareMaxTriangles = 2000000;  // the most the preparation makes (time and memory)
constexpr int kPrepareRefineRounds = 5;        // remeshing rounds of a refinement (PrepareOptions::refine_rounds)
constexpr int kPrepareMaxRemeshRounds = 10;    // pmp's default, and what every other remeshing runs

enum class PrepareMode { Auto, Off };

struct PrepareOptions {
  PrepareMode mode = PrepareMode::Auto;
  double edge_length = 0.0;  // > 0: remesh to this target edge length (Auto mode only)
  double feature_angle_deg = 44.0;  // creases kept by the remeshing (isotropic_remesh.h)
  // Samples per side of the distance check between the remeshed and the input surface
  // (core/quality/hausdorff.h; every vertex and centroid is sampled whatever this says).
  int distance_samples = 20000;
  // The triangle count above which a mesh with more than kPrepareHugeTrianglesPerPanel per
  // panel is coarsened (tests lower it to exercise coarsening on smaller meshes).
  int huge_triangles = kPrepareHugeTriangles;
  // Below this many triangles per panel (and at least kPrepareMinTrianglesPerPanel) the mesh is
  // refined when 50 per panel fit the cap. 20 is the rule before the 30 was measured (designs
  // saved then keep their prepared mesh, whose triangles their edits and paint name).
  int refine_triangles_per_panel = kPrepareRefineTrianglesPerPanel;
  // Isotropic remeshing rounds of a refinement below kPrepareMinTrianglesPerPanel per panel
  // (1..kPrepareMaxRemeshRounds; from there up to refine_triangles_per_panel it is always 5).
  // 10 is the rule before 5 was measured (the same as refine_triangles_per_panel's 20).
  int refine_rounds = kPrepareRefineRounds;
  // Empty, or one value > 0 per vertex of the mesh: a density the remeshing also sizes by
  // (times the density argument), not carried to the prepared mesh. The density expression:
  // the Remesher evaluates it on the prepared mesh itself, so carrying it would count it twice.
  std::vector<double> sizing_density;
};

struct PrepareReport {
  bool applied = false;  // the mesh was remeshed
  int triangles_in = 0;
  int triangles_out = 0;
  double target_edge = 0.0;  // the remeshing target (0 when not applied)
  // Two-sided sampled Hausdorff distance between the prepared and the input surface (0 when
  // not applied): absolute, and divided by the input's bounding-box diagonal.
  double distance = 0.0;
  double distance_relative = 0.0;
  std::vector<std::string> messages;  // one human sentence each
};

struct PreparedSurface {
  TriMesh mesh;  // the input itself when not applied
  // The density on `mesh`, of the same kind as given (per vertex or per face; empty if none).
  std::vector<double> density;
  PrepareReport report;
};

// mesh: clean (clean_mesh). density: empty, one value > 0 per vertex or one per face (per
// vertex wins when the counts coincide, as in the Remesher). Throws InputError for a panel
// count below 1 or one that would need more than kPrepareMaxTriangles at 20 per panel, an
// edge length that is not positive or would need more than that, or gives fewer triangles
// than panels, an edge length with mode Off, a negative distance_samples or huge_triangles, a
// refine_triangles_per_panel outside kPrepareMinTrianglesPerPanel..kPrepareTargetTrianglesPerPanel,
// a refine_rounds outside 1..kPrepareMaxRemeshRounds, or a density (or sizing_density) of the
// wrong size or with a value that is not finite and > 0.
PreparedSurface prepare_surface(const TriMesh& mesh, int panels, const std::vector<double>& density,
                                const PrepareOptions& options = {});

}  // namespace ff
