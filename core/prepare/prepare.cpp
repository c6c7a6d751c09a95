#include "core/prepare/prepare.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/prepare/isotropic_remesh.h"
#include "core/prepare/mesh_transfer.h"
#include "core/quality/hausdorff.h"
#include "core/util/error.h"
#include "core/util/index.h"
#include "core/util/short_number.h"
#include "core/util/with_commas.h"

namespace ff {

namespace {

// An estimated triangle count in a message ("about 12,345", "at least 12,345"), bounded: an edge length of 1e-10
// asks for 1e+22 triangles, past what llround can return, and one of 5e-324 for infinitely many.
std::string count_text(const char* how, double estimate) {
  return estimate < 1e15 ? how + (" " + with_commas(std::llround(estimate))) : "more than 1e+15";
}

// Area of an equilateral triangle with edge L.
double equilateral_area(double L) { return std::sqrt(3.0) / 4.0 * L * L; }
double edge_for_area(double a) { return std::sqrt(a / (std::sqrt(3.0) / 4.0)); }

// The band's remeshing rounds (see prepare_surface): fixed, not PrepareOptions::refine_rounds,
// since every design refined in the band was made with 5 (the band and its 5 rounds landed
// together).
constexpr int kBandRemeshRounds = 5;

// The triangle count a refinement for `panels` aims at: about kPrepareTargetTrianglesPerPanel
// each, within kPrepareMaxTriangles (dense: dense_factor, which the count is divided by).
double refined_count(int panels, double dense) {
  return std::min<double>(static_cast<double>(panels) * kPrepareTargetTrianglesPerPanel, kPrepareMaxTriangles / dense);
}

// Per-vertex values for the remeshing's sizing: as given, or per face averaged onto the
// vertices by area.
std::vector<double> sizing_density(const TriMesh& mesh, const std::vector<double>& density, bool per_vertex) {
  if (density.empty() || per_vertex) return density;
  std::vector<double> sum(mesh.positions.size(), 0.0), weight(mesh.positions.size(), 0.0);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const double a = std::max(face_area(mesh, f), 1e-300);
    for (const int v : mesh.triangles[at(f)]) {
      sum[at(v)] += a * density[at(f)];
      weight[at(v)] += a;
    }
  }
  std::vector<double> out(sum.size(), 1.0);
  for (size_t v = 0; v < out.size(); ++v)
    if (weight[v] > 0.0) out[v] = sum[v] / weight[v];
  return out;
}

// The sizing times the designer's sizing density (PrepareOptions::sizing_density), each
// divided by its largest value first (only ratios size the triangles, and two large
// densities' product could overflow).
std::vector<double> with_sizing(std::vector<double> sizing, const std::vector<double>& extra) {
  if (extra.empty()) return sizing;
  const double extra_max = *std::max_element(extra.begin(), extra.end());
  if (sizing.empty()) sizing.assign(extra.size(), 1.0);
  const double sizing_max = *std::max_element(sizing.begin(), sizing.end());
  for (size_t v = 0; v < sizing.size(); ++v) sizing[v] = (sizing[v] / sizing_max) * (extra[v] / extra_max);
  return sizing;
}

// How much denser than average the dense panels are: the area-weighted 90th percentile of
// density / mean density (1 for a uniform or missing density).
double dense_factor(const TriMesh& mesh, const std::vector<double>& vertex_density) {
  if (vertex_density.empty()) return 1.0;
  std::vector<std::pair<double, double>> samples;  // (face density, area)
  double area = 0.0, weighted = 0.0;
  for (int f = 0; f < mesh.num_faces(); ++f) {
    double d = 0.0;
    for (const int v : mesh.triangles[at(f)]) d += vertex_density[at(v)] / 3.0;
    const double a = face_area(mesh, f);
    samples.emplace_back(d, a);
    area += a;
    weighted += a * d;
  }
  if (!(area > 0.0) || !(weighted > 0.0)) return 1.0;
  std::sort(samples.begin(), samples.end());
  double below = 0.0, p90 = samples.back().first;
  for (const auto& [d, a] : samples) {
    below += a;
    if (below >= 0.9 * area) {
      p90 = d;
      break;
    }
  }
  return std::max(1.0, p90 / (weighted / area));
}

void check_density(const TriMesh& mesh, const std::vector<double>& density) {
  if (density.empty()) return;
  if (density.size() != mesh.positions.size() && density.size() != mesh.triangles.size())
    throw InputError("density has " + std::to_string(density.size()) + " values; expected one per vertex (" +
                     std::to_string(mesh.num_vertices()) + ") or one per triangle (" +
                     std::to_string(mesh.num_faces()) + ")");
  for (size_t i = 0; i < density.size(); ++i)
    if (!(density[i] > 0.0) || !std::isfinite(density[i]))
      throw InputError("density value " + std::to_string(i + 1) + " is " + std::to_string(density[i]) +
                       "; densities must be finite and greater than 0");
}

}  // namespace

PreparedSurface prepare_surface(const TriMesh& mesh, int panels, const std::vector<double>& density,
                                const PrepareOptions& options) {
  if (panels < 1) throw InputError("the number of panels must be at least 1");
  check_density(mesh, density);
  if (!options.sizing_density.empty()) {
    if (options.sizing_density.size() != mesh.positions.size())
      throw InputError("the sizing density has " + std::to_string(options.sizing_density.size()) +
                       " values; expected one per vertex (" + std::to_string(mesh.positions.size()) + ")");
    check_density(mesh, options.sizing_density);
  }
  const bool explicit_length = options.edge_length != 0.0;
  if (explicit_length && (!(options.edge_length > 0.0) || !std::isfinite(options.edge_length)))
    throw InputError("the edge length must be a positive number, got " + short_number(options.edge_length));
  if (explicit_length && options.mode == PrepareMode::Off)
    throw InputError("an edge length needs preparation on (it remeshes to that length)");
  if (options.distance_samples < 0) throw InputError("the number of distance samples must not be negative");
  if (options.huge_triangles < 0) throw InputError("the triangle count that makes a mesh huge must not be negative");
  if (options.refine_triangles_per_panel < kPrepareMinTrianglesPerPanel ||
      options.refine_triangles_per_panel > kPrepareTargetTrianglesPerPanel)
    throw InputError("the triangles per panel below which a mesh is refined must be " +
                     std::to_string(kPrepareMinTrianglesPerPanel) + " to " +
                     std::to_string(kPrepareTargetTrianglesPerPanel) + ", not " +
                     std::to_string(options.refine_triangles_per_panel));
  if (options.refine_rounds < 1 || options.refine_rounds > kPrepareMaxRemeshRounds)
    throw InputError("the remeshing rounds of a refinement must be 1 to " + std::to_string(kPrepareMaxRemeshRounds) +
                     ", not " + std::to_string(options.refine_rounds));

  PreparedSurface out;
  PrepareReport& r = out.report;
  r.triangles_in = mesh.num_faces();
  const long long faces = mesh.num_faces();
  const double per_panel = static_cast<double>(faces) / panels;
  const double area = total_area(mesh);
  // Every face degenerate (collinear corners): said as such, not as the edge length that a zero
  // area would make (the metric says the same with the preparation off).
  if (!(area > 0.0)) throw InputError("the surface has zero area: all " + with_commas(faces) + " faces are degenerate");
  const bool per_vertex = density.size() == mesh.positions.size();
  const std::vector<double> sizing = with_sizing(sizing_density(mesh, density, per_vertex), options.sizing_density);
  const double dense = dense_factor(mesh, sizing);
  const double dense_per_panel = per_panel / dense;
  const std::string panels_text = with_commas(panels) + (panels == 1 ? " panel" : " panels");

  auto keep = [&](const std::string& why) {
    out.mesh = mesh;
    out.density = density;
    r.triangles_out = r.triangles_in;
    r.messages.push_back(why);
    return out;
  };

  double target = 0.0;
  std::string reason;
  // From kPrepareMinTrianglesPerPanel up to the refine threshold: refined only where 50 per
  // panel fit the cap (always with kBandRemeshRounds, below).
  const bool band = !explicit_length && dense_per_panel >= kPrepareMinTrianglesPerPanel &&
                    dense_per_panel < options.refine_triangles_per_panel &&
                    static_cast<double>(panels) * dense * kPrepareTargetTrianglesPerPanel <= kPrepareMaxTriangles;
  const bool refining = !explicit_length && (dense_per_panel < kPrepareMinTrianglesPerPanel || band);
  if (options.mode == PrepareMode::Off) {
    return keep("preparation off: the " + with_commas(faces) + " triangles are used as they are (" +
                short_number(per_panel) + " per panel; 30 to 100 work best)");
  }
  if (explicit_length) {
    target = options.edge_length;
    const double estimate = area / equilateral_area(target);
    if (estimate > kPrepareMaxTriangles)
      throw InputError("an edge length of " + short_number(target) + " needs " + count_text("about", estimate) +
                       " triangles, more than the " + with_commas(kPrepareMaxTriangles) + " the preparation makes");
    if (estimate < panels)
      throw InputError("an edge length of " + short_number(target) + " gives about " + with_commas(std::llround(estimate)) +
                       " triangles, fewer than the " + panels_text + " asked for");
    reason = " triangles each, at the edge length asked for";
  } else if (refining) {
    if (static_cast<double>(panels) * dense * kPrepareMinTrianglesPerPanel > kPrepareMaxTriangles)
      throw InputError(
          panels_text + " need " + count_text("at least", panels * dense * kPrepareMinTrianglesPerPanel) +
          " triangles (20 per panel), more than the " + with_commas(kPrepareMaxTriangles) +
          " the preparation makes; ask for at most " +
          with_commas(static_cast<long long>(kPrepareMaxTriangles / (dense * kPrepareMinTrianglesPerPanel))) +
          " panels");
    target = edge_for_area(area / refined_count(panels, dense));
    reason = " triangles each (" + short_number(dense_per_panel) +
             (dense > 1.0 ? " where the density is highest" : "") + " before; 30 to 100 work best)";
  } else if (per_panel > kPrepareHugeTrianglesPerPanel && faces > options.huge_triangles) {
    target = edge_for_area(area / (static_cast<double>(panels) * kPrepareCoarsenTrianglesPerPanel));
    reason = " triangles each instead of " + with_commas(std::llround(per_panel)) +
             ": a mesh this fine costs time and memory the panels cannot show";
  } else {
    return keep("kept the " + with_commas(faces) + " triangles as they are: " + panels_text + " get about " +
                short_number(dense_per_panel) + " each" + (dense > 1.0 ? " where the density is highest" : ""));
  }

  IsotropicRemeshOptions remesh;
  remesh.target_edge_length = target;
  remesh.feature_angle_deg = options.feature_angle_deg;
  remesh.vertex_density = sizing;
  // A refinement runs 5 remeshing rounds, not 10: the last five only even the triangles out a
  // little more (bench/README.md, "Preparation below 30 triangles per panel"). In the band
  // (hyperboloid_s4.off to 137k triangles: 2.2 s instead of 4.0, smallest angle at the 1st
  // percentile 36.9 degrees instead of 37.8; every shared mesh at 28 and 23 per panel, seeds
  // 1-3: 78 of 78 valid either way, 89 -> 67 s) and below 20 (every shared mesh at 15 and 10
  // per panel, seeds 1-2: 52 of 52 valid either way, 185 -> 130 s, Hausdorff to the input 0.99
  // of it). Below 20 the rounds are an option: designs saved before keep their 10.
  // An explicit edge length and a coarsening run 10, as every design made with them did.
  remesh.iterations = !refining ? kPrepareMaxRemeshRounds : band ? kBandRemeshRounds : options.refine_rounds;
  // The preparation's own limit with room for the splitting's overshoot (the area estimate
  // above keeps a sound mesh well inside it).
  remesh.max_triangles = 2LL * kPrepareMaxTriangles;
  IsotropicRemeshResult result;
  try {
    result = isotropic_remesh(mesh, remesh);
  } catch (const InputError& e) {
    throw InputError("preparing the mesh for " + panels_text + ": " + e.what());
  }
  out.mesh = std::move(result.mesh);
  if (!density.empty() && !per_vertex) {
    out.density = transfer_face_field(mesh, density, out.mesh);
  } else if (!density.empty()) {
    // The remeshing carries its sizing; without a sizing density that is the density.
    out.density = options.sizing_density.empty() ? std::move(result.vertex_density)
                                                 : transfer_vertex_values(mesh, density, out.mesh);
  }
  r.applied = true;
  r.triangles_out = out.mesh.num_faces();
  r.target_edge = target;
  const std::string verb = explicit_length ? "remeshed" : (r.triangles_out >= r.triangles_in ? "refined" : "coarsened");
  r.messages.push_back(verb + " " + with_commas(faces) + " triangles to " + with_commas(r.triangles_out) +
                       " (target edge " + short_number(target) +
                       (sizing.empty() ? "" : ", shorter where the density is higher") + ") so " + panels_text +
                       " get about " + short_number(static_cast<double>(r.triangles_out) / panels) + reason);
  if (result.feature_edges > 0)
    r.messages.push_back("kept " + with_commas(result.feature_edges) + " boundary and crease edges (sharper than " +
                         short_number(options.feature_angle_deg) + " degrees) as curves, " +
                         with_commas(result.feature_corners) + (result.feature_corners == 1 ? " corner" : " corners") +
                         " fixed");
  if (out.mesh.num_faces() < panels)
    throw InputError("the remeshed surface has " + with_commas(out.mesh.num_faces()) + " triangles, fewer than the " +
                     panels_text + " asked for; use a shorter edge length");
  // How far the remeshing moved the surface: vertices are projected onto the input, so the
  // distance is the chord error of the new triangles (and of the input's, seen from them).
  const HausdorffResult distance = hausdorff_distance(mesh, out.mesh, options.distance_samples);
  const double diagonal = bbox_diagonal(mesh);
  r.distance = distance.two_sided;
  r.distance_relative = diagonal > 0.0 ? r.distance / diagonal : 0.0;
  r.messages.push_back("the prepared surface is within " + short_number(r.distance) + " of the input (" +
                       short_number(100.0 * r.distance_relative) + "% of its bounding-box diagonal, " +
                       short_number(r.distance / target) + " of the target edge; sampled both ways)");
  return out;
}

}  // namespace ff
