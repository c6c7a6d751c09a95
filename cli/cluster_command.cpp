// `flatfacet cluster`: the Lloyd phase on its own, labels per input triangle + a summary.
#include <chrono>
#include <string>
#include <vector>

#include "cli/args.h"
#include "cli/commands.h"
#include "cli/input.h"
#include "core/util/json_writer.h"
#include "cli/output.h"
#include "core/mesh/face_map.h"
#include "core/remesher.h"

namespace ff::cli {

namespace {

std::string summary_json(const LoadedInput& in, const Remesher& r, double cluster_s, double total_s,
                         const std::string& seeding) {
  const RemeshParams& p = r.params();
  const EnergyTerms e = r.energy();
  JsonWriter j;
  j.begin_object();
  j.value("input", in.path);
  j.value("input_vertices", in.raw.mesh.num_vertices());
  j.value("input_triangles", in.raw.mesh.num_faces());
  j.value("vertices", r.mesh().num_vertices());
  j.value("triangles", r.mesh().num_faces());
  j.value("components", r.topology().num_components);
  j.begin_array("cleanup");
  for (const std::string& m : in.clean.report.messages()) j.value(nullptr, m);
  j.end_array();
  j.value("clusters", r.clustering().num_clusters());
  j.value("iterations", r.lloyd_iterations_done());
  j.value("converged", r.converged());
  j.value("teleports", r.teleports_done());
  j.value("seed", static_cast<std::uint64_t>(p.seed));
  j.value("seeding", seeding);
  j.begin_object("weights");
  j.value("euclidean", p.weights.euclidean).value("l2", p.weights.l2).value("l21", p.weights.l21);
  j.value("density", p.weights.density);
  j.end_object();
  j.value("expected_cluster_diameter", r.metric().diameter());
  j.begin_object("energy");
  j.value("euclidean", e.euclidean).value("l2", e.l2).value("l21", e.l21).value("density", e.density);
  j.value("total", e.total());
  j.end_object();
  j.begin_object("timings_s");
  j.value("read", in.read_seconds).value("clean", in.clean_seconds).value("cluster", cluster_s);
  j.value("total", total_s);
  j.end_object();
  j.end_object();
  return j.str();
}

}  // namespace

int run_cluster(const std::vector<std::string>& argv) {
  const auto t_start = std::chrono::steady_clock::now();
  std::set<std::string> with_value = {"panels", "seed", "weights", "density", "iterations", "labels", "summary", "seeding"};
  with_value.insert(repair_option_names().begin(), repair_option_names().end());
  std::set<std::string> switches = {"no-teleport"};
  switches.insert(repair_switch_names().begin(), repair_switch_names().end());
  const Args args = parse_args(argv, with_value, switches);
  if (args.positional.size() != 1) throw UsageError("expected exactly one INPUT mesh (see flatfacet --help)");
  if (!args.has("panels")) throw UsageError("--panels N is required");
  if (!args.has("labels")) throw UsageError("--labels LABELS.txt is required");

  RemeshParams params;
  params.panels = static_cast<int>(args.get_int("panels", 0, 1, 10'000'000));
  params.seed = static_cast<std::uint64_t>(args.get_int("seed", 1, 0, RemeshParams::kMaxSeed));
  params.lloyd_iterations = static_cast<int>(args.get_int("iterations", 20, 0, 100000));
  if (args.has("weights")) params.weights = parse_weights(args.get("weights"));
  const std::string seeding = args.get("seeding", "farthest");
  if (seeding == "random")
    params.seeding = SeedingMethod::Random;
  else if (seeding != "farthest")
    throw UsageError("--seeding: expected farthest or random, got '" + seeding + "'");
  if (args.flags.count("no-teleport")) params.teleport_interval = 0;
  params.make_panels = false;  // the Lloyd phase only

  require_outputs_spare_inputs({args.get("labels"), args.get("summary")}, {args.positional[0], args.get("density")});
  const LoadedInput in = load_input(args.positional[0], parse_repair(args));
  if (args.has("density")) params.density = load_density(args.get("density"), in);

  const auto t_cluster = std::chrono::steady_clock::now();
  Remesher remesher(in.clean.mesh, params);
  remesher.run();
  const double cluster_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_cluster).count();

  const std::vector<int> labels =
      values_for_input_faces(in.clean, in.raw.mesh, remesher.topology(), remesher.clustering().labels);
  std::string text;
  text.reserve(labels.size() * 4);
  for (int l : labels) text += std::to_string(l) + "\n";

  const double total_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  const std::string summary = args.has("summary") ? summary_json(in, remesher, cluster_s, total_s, seeding) : "";
  std::vector<OutputFile> outputs = {{args.get("labels"), text}};
  if (args.has("summary")) outputs.push_back({args.get("summary"), summary});
  write_files_atomic(outputs);
  return 0;
}

}  // namespace ff::cli
