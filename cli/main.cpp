// flatfacet: the command-line front of the core. Exit codes (DESIGN.md 4): 0 done,
// 3 written but some panels invalid, 2 usage or input error (one line on stderr, nothing
// written), 1 internal error.
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
    "  cluster INPUT --panels N --labels LABELS.txt [--summary SUMMARY.json] [--seed S]\n"
    "          [--weights euclidean=1,l2=1,l21=1,density=1] [--density FILE]\n"
    "          [--iterations K] [--seeding farthest|random] [--no-teleport]\n"
    "      Cluster the surface into N contiguous regions (the Lloyd phase). LABELS.txt gets\n"
    "      one cluster id (0..N-1) per input triangle, in input order (polygons count as the\n"
    "      triangles they are split into, in order).\n"
    "      Weights: euclidean (round, even panels), l2 and l21 (follow the curvature), each\n"
    "      0..1e6; density (how strongly a density field sets panel size), 0..8. The boundary\n"
    "      weight belongs to the panel phase and has no effect here.\n"
    "\n"
    "INPUT is an OBJ, OFF, STL (ASCII or binary) or PLY (ASCII or binary little-endian) mesh.\n"
    "--density FILE: one positive number per input vertex (or per triangle); higher values\n"
    "give smaller panels.\n";

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::fputs(kUsage, args.empty() ? stderr : stdout);
    return args.empty() ? 2 : 0;
  }
  if (args[0] == "--version") {
    std::puts("flatfacet 0.1.0");
    return 0;
  }
  const std::string command = args[0];
  args.erase(args.begin());
  try {
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
