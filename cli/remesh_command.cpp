// `flatfacet remesh`: the whole pipeline (prepare -> Lloyd phase -> panel phase -> quality),
// writing the panels OBJ and the report JSON (DESIGN.md 4).
#include <chrono>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "cli/args.h"
#include "cli/commands.h"
#include "cli/fabrication_options.h"
#include "cli/input.h"
#include "cli/output.h"
#include "cli/remesh_report.h"
#include "core/density/density_field.h"
#include "core/density/direction_expression.h"
#include "core/density/expression.h"
#include "core/fabricate/number_text.h"
#include "core/mesh/mesh_io.h"
#include "core/panels/panel_export.h"
#include "core/prepare/prepare.h"
#include "core/quality/report.h"
#include "core/quality/report_json.h"
#include "core/remesh_params_json.h"
#include "core/remesher.h"
#include "core/util/error.h"

namespace ff::cli {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

constexpr long long kMaxIterations = RemeshParams::kMaxIterations;  // k1 and k2

// "K1,K2": at most K1 Lloyd iterations, at most K2 panel rounds.
std::pair<int, int> parse_iterations(const std::string& text) {
  const size_t comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos)
    throw UsageError("--iterations: expected K1,K2 (Lloyd iterations, panel rounds), got '" + text + "'");
  const long long k1 = parse_int(text.substr(0, comma), "--iterations K1", 0, kMaxIterations);
  // At least one panel round: without one there are no panels to write.
  const long long k2 = parse_int(text.substr(comma + 1), "--iterations K2", 1, kMaxIterations);
  return {static_cast<int>(k1), static_cast<int>(k2)};
}

// "DIR,STRETCH": DIR one of none, x, y, z, maxCurvature, minCurvature, or "expr:EX,EY,EZ" (a
// procedural direction, core/density/direction_expression.h); STRETCH 1..10, after the last
// comma (the expression has commas of its own).
Anisotropy parse_anisotropy(const std::string& text) {
  const size_t comma = text.rfind(',');
  Anisotropy a;
  const std::string dir = comma == std::string::npos ? text : text.substr(0, comma);
  const std::string prefix = "expr:";
  const bool procedural = dir.compare(0, prefix.size(), prefix) == 0;
  if (comma == std::string::npos || (!procedural && !set_anisotropy_direction(a, dir)))
    throw UsageError(
        "--anisotropy: expected DIR,STRETCH with DIR none, x, y, z, maxCurvature, minCurvature or expr:EX,EY,EZ, got '" +
        text + "'");
  if (procedural) {
    set_anisotropy_direction(a, "expression");
    a.expression = dir.substr(prefix.size());
    try {
      parse_direction_expression(a.expression);  // its columns count from after "expr:"
    } catch (const InputError& e) {
      throw UsageError("--anisotropy: " + std::string(e.what()));
    }
  }
  a.stretch = parse_double(text.substr(comma + 1), "--anisotropy STRETCH");
  if (!(a.stretch >= 1.0 && a.stretch <= Anisotropy::kMaxStretch))
    throw UsageError("--anisotropy: STRETCH must be between 1 and 10, got '" + text.substr(comma + 1) + "'");
  return a;
}

struct Options {
  RemeshParams params;
  std::string input, seeding, out, report;
  FabricationRequest fabrication;
  std::string density;  // a file, read once the mesh is loaded (its length is checked against it)
  SubdivisionRequest subdivision;
  std::string edits;    // a JSON file: the edits array (remesh_params_json.h)
  PrepareOptions prepare;
  CleanOptions repair;  // --fill-holes, --largest-part
};

Options parse_options(const std::vector<std::string>& argv) {
  std::set<std::string> with_value = {"panels",  "seed",        "weights",      "density",    "iterations",
                                      "out",     "report",      "seeding",      "min-angle",  "edits",
                                      "prepare", "edge-length", "density-expr", "anisotropy", "retries",
                                      "coplanar-angle"};
  with_value.insert(fabrication_option_names().begin(), fabrication_option_names().end());
  with_value.insert(subdivision_option_names().begin(), subdivision_option_names().end());
  with_value.insert(repair_option_names().begin(), repair_option_names().end());
  std::set<std::string> switches = {"single-point-nodes", "no-optimize", "no-teleport", "glass"};
  switches.insert(repair_switch_names().begin(), repair_switch_names().end());
  const Args args = parse_args(argv, with_value, switches);
  if (args.positional.size() != 1) throw UsageError("expected exactly one INPUT mesh (see flatfacet --help)");
  if (!args.has("panels")) throw UsageError("--panels N is required");
  Options o;
  o.input = args.positional[0];
  RemeshParams& p = o.params;
  p.panels = static_cast<int>(args.get_int("panels", 0, 1, 10'000'000));
  p.seed = static_cast<std::uint64_t>(args.get_int("seed", 1, 0, RemeshParams::kMaxSeed));
  if (args.has("iterations")) std::tie(p.lloyd_iterations, p.panel_rounds) = parse_iterations(args.get("iterations"));
  p.retries = static_cast<int>(args.get_int("retries", p.retries, 0, RemeshParams::kMaxRetries));
  if (args.has("weights")) p.weights = parse_weights(args.get("weights"));
  o.seeding = args.get("seeding", "farthest");
  if (o.seeding == "random")
    p.seeding = SeedingMethod::Random;
  else if (o.seeding != "farthest")
    throw UsageError("--seeding: expected farthest or random, got '" + o.seeding + "'");
  if (args.flags.count("no-teleport")) p.teleport_interval = 0;
  p.single_point_nodes = args.flags.count("single-point-nodes") != 0;
  p.optimize_planes = args.flags.count("no-optimize") == 0;
  p.make_panels = true;
  p.glass = args.flags.count("glass") != 0;
  if (args.has("min-angle")) {
    p.min_corner_angle_deg = parse_double(args.get("min-angle"), "--min-angle");
    // Above 60 no triangle qualifies, so no mesh could pass.
    if (!(p.min_corner_angle_deg >= 0.0 && p.min_corner_angle_deg <= 60.0))
      throw UsageError("--min-angle: expected degrees between 0 and 60, got '" + args.get("min-angle") + "'");
  }
  if (args.has("coplanar-angle")) {
    p.coplanar_angle_deg = parse_double(args.get("coplanar-angle"), "--coplanar-angle");
    if (!(p.coplanar_angle_deg >= 0.0 && p.coplanar_angle_deg <= 10.0))
      throw UsageError("--coplanar-angle: expected degrees between 0 and 10, got '" + args.get("coplanar-angle") + "'");
  }
  o.out = args.get("out");
  o.report = args.get("report");
  if (args.has("out") && o.out.empty()) throw UsageError("--out: empty file name");
  if (args.has("report") && o.report.empty()) throw UsageError("--report: empty file name");
  o.fabrication = parse_fabrication(args);
  const FabricationRequest& f = o.fabrication;
  const std::string* names[] = {&o.out, &o.report, &f.parts, &f.sheets, &f.solid};
  for (int a = 0; a < 5; ++a)
    for (int b = a + 1; b < 5; ++b)
      if (!names[a]->empty() && *names[a] == *names[b])
        throw UsageError("--out, --report, --parts, --sheets and --solid name the same file '" + *names[a] + "'");
  if (args.has("edits")) {
    o.edits = args.get("edits");
    if (o.edits.empty()) throw UsageError("--edits: empty file name");
  }
  const std::string prepare = args.get("prepare", "auto");
  if (prepare == "off")
    o.prepare.mode = PrepareMode::Off;
  else if (prepare != "auto")
    throw UsageError("--prepare: expected auto or off, got '" + prepare + "'");
  if (args.has("edge-length")) {
    o.prepare.edge_length = parse_double(args.get("edge-length"), "--edge-length");
    if (!(o.prepare.edge_length > 0.0))
      throw UsageError("--edge-length: expected a positive length, got '" + args.get("edge-length") + "'");
    if (o.prepare.mode == PrepareMode::Off)
      throw UsageError("--edge-length remeshes the surface: it cannot go with --prepare off");
  }
  // Edits name triangles of the cleaned mesh, which preparation would renumber.
  if (!o.edits.empty()) {
    if (args.has("edge-length") || (args.has("prepare") && prepare == "auto"))
      throw UsageError("--edits names triangles of the cleaned mesh: it cannot go with --prepare auto or --edge-length");
    o.prepare.mode = PrepareMode::Off;
  }
  if (args.has("density-expr")) {
    p.density_expression = args.get("density-expr");
    try {
      Expression::parse(p.density_expression);  // syntax errors before the mesh is read
    } catch (const InputError& e) {
      throw UsageError(std::string("--density-expr: ") + e.what());
    }
  }
  if (args.has("anisotropy")) p.anisotropy = parse_anisotropy(args.get("anisotropy"));
  if (args.has("density")) {
    o.density = args.get("density");
    if (o.density.empty()) throw UsageError("--density: empty file name");
  }
  o.subdivision = parse_subdivision(args);
  o.repair = parse_repair(args);
  // A density file holds values per input vertex or triangle; the subdivided mesh has others.
  if (o.subdivision.levels > 0 && !o.density.empty()) throw UsageError("--density cannot be combined with --subdivide");
  require_outputs_spare_inputs({o.out, o.report, f.parts, f.sheets, f.solid}, {o.input, o.density, o.edits});
  return o;
}

// One stderr line naming the parts whose inner face folds over (the first eight of them).
std::string folded_parts_line(const std::vector<std::string>& labels, double thickness, const std::string& units,
                              bool per_panel) {
  // With --panel-thickness a folded part may have its own thickness, not the default.
  std::string line = "flatfacet remesh: at a thickness of " + number_text(thickness, 6) + " " + units +
                     (per_panel ? " (and those of --panel-thickness)" : "") + " the inner face folds over on " +
                     std::to_string(labels.size()) + (labels.size() == 1 ? " part (" : " parts (");
  for (size_t k = 0; k < labels.size() && k < 8; ++k) line += (k ? ", " : "") + labels[k];
  if (labels.size() > 8) line += ", ...";
  return line + "), which cannot be cut as drawn: use thinner material, or fewer and larger panels\n";
}

}  // namespace

int run_remesh(const std::vector<std::string>& argv) {
  const auto t_start = Clock::now();
  Options o = parse_options(argv);

  RemeshTimings timings;
  LoadedInput in = load_input(o.input, o.repair);
  subdivide_input(in, o.subdivision);
  if (!o.density.empty()) o.params.density = load_density(o.density, in);
  if (!o.edits.empty()) {
    std::ifstream file(o.edits, std::ios::binary);
    if (!file) throw UsageError("--edits: cannot open '" + o.edits + "'");
    std::ostringstream text;
    text << file.rdbuf();
    o.params.edits = panel_edits_from_json(text.str());  // faces: of the cleaned mesh
  }
  const int requested = o.params.panels;
  // Preparation: the resolution the panel count needs (prepare.h); the density follows.
  // A density expression sizes the triangles as a density file does (the Remesher evaluates
  // it again on the prepared mesh).
  if (!o.params.density_expression.empty() && o.prepare.mode == PrepareMode::Auto)
    o.prepare.sizing_density = expression_density(in.clean.mesh, o.params.density_expression);
  PreparedSurface prepared = prepare_surface(in.clean.mesh, o.params.panels, o.params.density, o.prepare);
  o.params.density = std::move(prepared.density);
  // Building the Remesher builds the topology and the face data: part of preparing.
  Remesher remesher(std::move(prepared.mesh), o.params);
  timings.prepare = seconds_since(t_start);

  // Step the state machine ourselves to time the Lloyd and the panel stages apart.
  while (!remesher.done()) {
    const Stage stage = remesher.progress().stage;
    const auto t0 = Clock::now();
    remesher.step();
    (stage == Stage::Seeding || stage == Stage::Lloyd ? timings.cluster : timings.panels) += seconds_since(t0);
  }

  const auto t_quality = Clock::now();
  QualityOptions quality_options;
  quality_options.glass = o.params.glass;
  quality_options.min_corner_angle_deg = o.params.min_corner_angle_deg;
  if (!prepared.report.applied) quality_options.input_crossings = in.crossings;  // the loaded mesh's, checked
  const QualityReport quality =
      measure_quality(remesher.mesh(), remesher.topology(), remesher.panels(), quality_options);
  timings.quality = seconds_since(t_quality);
  timings.total = seconds_since(t_start);

  const RemeshRun run{in, remesher, quality, requested, o.seeding, timings, prepared.report};
  std::vector<OutputFile> outputs;
  if (!o.out.empty()) {
    // measure_quality has checked every index, so the remapping cannot go out of range.
    outputs.push_back({o.out, panels_obj(remesher.panels(), panels_obj_comment(run))});
  }
  if (!o.report.empty()) outputs.push_back({o.report, remesh_report_json(run)});
  std::vector<std::string> folded;
  for (OutputFile& file : fabrication_outputs(o.fabrication, remesher.panels(), &folded))
    outputs.push_back(std::move(file));
  if (outputs.empty())
    std::fputs(remesh_summary_line(run).c_str(), stdout);
  else
    write_files_atomic(outputs);
  // Exit 3 says only that something is invalid: name what, on stderr, so a run with --out
  // alone does not end in silence.
  const std::string invalid = invalid_panels_phrase(remesher.panels(), quality);
  if (!invalid.empty()) {
    const int solves = remesher.retries_done() + 1;
    std::fprintf(stderr,
                 "flatfacet: %s after %d solve%s; --report lists them; another --seed or --panels count (more or "
                 "fewer) may make every panel valid\n",
                 invalid.c_str(), solves, solves == 1 ? "" : "s");
  }
  // Valid panels that still close a hole or join two sheets (topology_preserved false): the
  // same exit 3, named.
  const std::string topology = topology_phrase(quality);
  if (!topology.empty() && invalid.empty())
    std::fprintf(stderr, "flatfacet: %s; --report has both; another --seed or --panels count may keep it\n",
                 topology.c_str());
  // Panels passing through each other: not yet avoided by the solver nor counted invalid
  // (report.h), so said here whatever the exit code.
  const std::string crossing = crossing_phrase(quality);
  if (!crossing.empty()) std::fprintf(stderr, "flatfacet: warning: %s\n", crossing.c_str());
  // Flat to 1e-9 by construction; not where the coordinates cannot hold that (far from the
  // origin): the file is still written (fabrication tolerances are ~1e-4), the designer told.
  const std::string planarity = planarity_phrase(quality);
  if (!planarity.empty()) std::fprintf(stderr, "flatfacet: warning: %s\n", planarity.c_str());
  // Written, like invalid panels (exit 3): the designer sees the parts and can choose a
  // thinner material or larger panels.
  if (!folded.empty()) {
    const FabricationOptions& fab = o.fabrication.options;
    std::fputs(folded_parts_line(folded, fab.thickness, unit_name(fab.units), !fab.panel_thickness.empty()).c_str(),
               stderr);
  }
  return result_valid(remesher.panels(), quality) && folded.empty() ? 0 : 3;
}

}  // namespace ff::cli
