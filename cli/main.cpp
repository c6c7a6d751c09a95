// flatfacet: the command-line front of the core. Exit codes (DESIGN.md 4): 0 done,
// 3 written but some panels invalid or the topology changed, 2 usage or input error (one
// line on stderr, nothing written), 1 internal error.
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "cli/args.h"
#include "cli/commands.h"
#include "core/util/error.h"

namespace {

const char* kUsage =
    "usage: flatfacet <command> [options]\n"
    "\n"
    "commands:\n"
    "  remesh INPUT --panels N [--out PANELS.obj] [--report REPORT.json] [--parts PARTS.csv]\n"
    "          [--seed S]\n"
    "          [--weights euclidean=1,l2=1,l21=1,density=1,boundary=1] [--density FILE]\n"
    "          [--density-expr EXPR] [--anisotropy DIR,STRETCH]\n"
    "          [--iterations K1,K2] [--retries R] [--seeding farthest|random] [--no-teleport]\n"
    "          [--single-point-nodes] [--no-optimize] [--glass] [--min-angle DEG]\n"
    "          [--coplanar-angle DEG] [--edits EDITS.json]\n"
    "          [--thickness T] [--side inside|outside] [--units mm|cm|m|in|ft] [--mesh-units U]\n"
    "          [--sheets SHEETS.svg|SHEETS.dxf] [--sheet-size W,H] [--solid SOLID.obj]\n"
    "          [--panel-thickness P3=T,P7=T] [--boundary-cut square|plumb|DEG] [--up x|y|z]\n"
    "          [--subdivide N [--crease-angle DEG]]\n"
    "          [--prepare auto|off] [--edge-length L] [--fill-holes N] [--largest-part]\n"
    "      Remesh the surface into N exactly planar panels. PANELS.obj gets one polygon per\n"
    "      panel on shared vertices; REPORT.json the quality (planarity, Hausdorff distance,\n"
    "      topology, valences, invalid panels) and timings. With neither, one summary line is\n"
    "      printed. PARTS.csv (or .json): one row per panel (sides, area, perimeter, plane,\n"
    "      edge lengths, chamfer angles and neighbours, corner angles, outlines laid flat) and\n"
    "      a total. The mesh is taken to be in metres (--mesh-units to change); outputs are in\n"
    "      --units (default: the mesh's), T too. --thickness T: panels of that thickness, the\n"
    "      material behind the surface (--side inside, default) or in front of it; adds the inner\n"
    "      outlines. --sheets: the outlines packed on W x H sheets (default 2440 x 1220 mm).\n"
    "      --solid: each panel as a closed prism, in --units (needs --thickness).\n"
    "      --panel-thickness P3=T,...: those panels (labels of the parts list) get their own\n"
    "      thickness; the edge cuts keep the inner faces meeting. --boundary-cut: boundary\n"
    "      edges square (default), plumb (holding the --up axis, default z) or DEG from square.\n"
    "      A cluster that cannot be one panel is left out and reported as invalid.\n"
    "      --iterations K1,K2: at most K1 Lloyd iterations (default 20) and K2 panel rounds\n"
    "      (default 100, at least 1; they stop at the first valid result, or when 50 rounds in\n"
    "      a row did not lower the fewest invalid panels). --retries R (0..10, default 8): when\n"
    "      panels end invalid, solve again from a new seeding (derived from the seed) up to R\n"
    "      times and keep the result with the fewest invalid panels; 0: never. A run valid at\n"
    "      once never retries. --single-point-nodes: where 4+\n"
    "      planes meet, make them meet in one point instead of splitting the node into\n"
    "      valence-3 nodes. --no-optimize: skip the final fit of the planes to the surface.\n"
    "      The boundary weight (0..1e6) pulls faces towards the panel whose polygon covers them.\n"
    "      --glass: cut each concave panel at its inside corners into coplanar convex pieces\n"
    "      (labelled P12a, P12b, ... in the parts list). --min-angle DEG (0..60, default 0 =\n"
    "      none): no panel corner below DEG; the solver avoids them and those left make their\n"
    "      panels invalid (\"acute_corner\" in the report).\n"
    "      --coplanar-angle DEG (0..10, default 1, the paper's): neighbouring panels whose planes\n"
    "      differ by less than DEG share one plane, unless the two planes meet near them (as on\n"
    "      a curved surface); 0: none share.\n"
    "      --subdivide N (0..16): first subdivide the input as a control mesh N levels (Loop when\n"
    "      every face is a triangle, else Catmull-Clark on the file's polygons; each level makes\n"
    "      4x the faces, at most 4 million triangles), so a coarse model can get more panels than\n"
    "      it has faces. Boundaries stay sharp curves; --crease-angle DEG (0..180) also keeps\n"
    "      sharp every edge whose faces' normals differ by more than DEG. Not with --density.\n"
    "      --edits EDITS.json: per-panel edits applied in order to the solved design, panels\n"
    "      named by a triangle inside them (0-based, of the cleaned mesh): [{\"op\":\"split\",\n"
    "      \"face\":12}, {\"op\":\"merge\",\"face\":3,\"with\":40}, {\"op\":\"lock\",\"face\":7},\n"
    "      {\"op\":\"unlock\",\"face\":7}] (the page's format). Implies --prepare off (refused\n"
    "      with --prepare auto or --edge-length), so edits made on the page replay here when\n"
    "      the page did not prepare the mesh either.\n"
    "      --prepare auto (default): a mesh with fewer than 30 triangles per panel is first\n"
    "      remeshed to about 50 per panel (creases above 44 degrees and boundaries kept, finer\n"
    "      where --density or --density-expr is higher; from 20 to 30 per panel only when 50\n"
    "      per panel stays within 2,000,000 triangles), one with over 1000 per panel and over\n"
    "      400,000 triangles to about 100 per panel; other meshes are used as they are. The report's\n"
    "      \"prepare\" says what was done. --prepare off: always as they are. --edge-length L:\n"
    "      remesh to that target edge length (in mesh units) whatever the panel count.\n"
    "      Exit 0: every panel valid and the topology kept; 3: written, some panels invalid\n"
    "      (counted by problem on stderr, listed in the report) or the topology changed.\n"
    "      The input is repaired first (the report's \"cleanup\" and \"repair\" say how): coincident\n"
    "      vertices welded, degenerate, duplicate and sliver faces removed, orientation made\n"
    "      consistent. --fill-holes N (0..500, default 0 = off): fill every hole (boundary loop)\n"
    "      of at most N edges. A mesh with non-manifold edges (three or more faces on an edge) is\n"
    "      refused, naming the edge, and so is a part far from the rest; --largest-part: cut the\n"
    "      mesh at such edges and keep only its largest part, dropping every other part (the\n"
    "      report says what was dropped).\n"
    "\n"
    "  cluster INPUT --panels N --labels LABELS.txt [--summary SUMMARY.json] [--seed S]\n"
    "          [--weights euclidean=1,l2=1,l21=1,density=1] [--density FILE]\n"
    "          [--iterations K] [--seeding farthest|random] [--no-teleport]\n"
    "          [--fill-holes N] [--largest-part]\n"
    "      Cluster the surface into N contiguous regions (the Lloyd phase). LABELS.txt gets\n"
    "      one cluster id (0..N-1) per input triangle, in input order (polygons count as the\n"
    "      triangles they are split into, in order; -1 for one --largest-part left out).\n"
    "      Weights: euclidean (round, even panels), l2 and l21 (follow the curvature), each\n"
    "      0..1e6; density (how strongly a density field sets panel size), 0..8. The boundary\n"
    "      weight belongs to the panel phase and has no effect here.\n"
    "\n"
    "INPUT is an OBJ, OFF, STL (ASCII or binary) or PLY (ASCII or binary little-endian) mesh.\n"
    "--density FILE: one positive number per input vertex (or per triangle); higher values\n"
    "give smaller panels.\n"
    "--density-expr EXPR: a procedural density per vertex (multiplies --density), e.g.\n"
    "'1 + 3 * smoothstep(0.45, 0.55, u)'. Variables x y z (world), u v w (0..1 across the\n"
    "bounding box), nx ny nz (normal), k1 k2 H K (curvatures), curv (scale-free curvature),\n"
    "border (distance to the surface's edge over the bounding box diagonal, 1 if closed);\n"
    "operators + - * / ^ % < <= > >= == != && || ! ?:; functions sin cos tan asin acos atan\n"
    "atan2 sqrt exp log log10 abs sign floor ceil round pow min max clamp smoothstep step\n"
    "mix mod if; constants pi e. It must be > 0 everywhere.\n"
    "--anisotropy DIR,STRETCH: panels about STRETCH (1..10) times longer along DIR: x, y, z,\n"
    "maxCurvature or minCurvature (the principal directions), none, or expr:EX,EY,EZ, a\n"
    "direction per face from three expressions of the density language evaluated at its\n"
    "centroid (nx ny nz: the face normal), e.g. --anisotropy 'expr:-y, x, 0,3' (a vortex\n"
    "around the z axis, stretch 3; the stretch follows the last comma). Faces where it is zero\n"
    "or along the normal stay isotropic (counted in the report).\n";

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::fputs(kUsage, args.empty() ? stderr : stdout);
    return args.empty() ? 2 : 0;
  }
  if (args[0] == "--version") {
    std::printf("flatfacet %s\n", ff::kVersion);
    return 0;
  }
  const std::string command = args[0];
  args.erase(args.begin());
  // "flatfacet remesh --help": the usage, not "unknown option --help" (only as the command's
  // first word: "--out -h" names a file).
  if ((command == "remesh" || command == "cluster") && !args.empty() && (args[0] == "--help" || args[0] == "-h")) {
    std::fputs(kUsage, stdout);
    return 0;
  }
  try {
    if (command == "remesh") return ff::cli::run_remesh(args);
    if (command == "cluster") return ff::cli::run_cluster(args);
    std::fprintf(stderr, "flatfacet: unknown command '%s' (try flatfacet --help)\n", command.c_str());
    return 2;
  } catch (const ff::cli::UsageError& e) {
    std::fprintf(stderr, "flatfacet %s: %s\n", command.c_str(), e.what());
    return 2;
  } catch (const ff::InputError& e) {
    std::fprintf(stderr, "flatfacet %s: %s\n", command.c_str(), e.what());
    return 2;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "flatfacet %s: not enough memory for this mesh\n", command.c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "flatfacet %s: internal error: %s\n", command.c_str(), e.what());
    return 1;
  }
}
