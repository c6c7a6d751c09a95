// The final plane fit (Remesher::optimize_planes, plane_fit.h; beyond the paper): once the
// panel rounds end valid, each plane is refitted to its faces (and border) and kept only
// where the panels stay valid. So it never makes a panel invalid, and the panels come closer
// to the surface. It lowers a least-squares distance, not the largest one, so in one run the
// two-sided Hausdorff distance may stay or even rise (bump 120 at seed 1: 0.0083 -> 0.0090;
// bunny 200 at seed 2: 0.0159 -> 0.0176, a node pushed off the surface) and falls in most
// (bump at seeds 2-3: by 22-26%); hence seeds 1-3 per case, their geometric mean ratio at
// most 1.05 for each case and below 0.95 over the set (0.91 when written).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "core/quality/report.h"
#include "core/remesher.h"
#include "core/shapes/hard_cases.h"
#include "panel_checks.h"
#include "test_meshes.h"

namespace ff {
namespace {

struct FitCase {
  std::string name;
  std::function<TriMesh()> mesh;
  int panels;
};

double hausdorff(const TriMesh& mesh, int panels, std::uint64_t seed, bool optimize) {
  RemeshParams p;
  p.panels = panels;
  p.seed = seed;
  p.optimize_planes = optimize;
  Remesher r(mesh, p);
  r.run();
  EXPECT_TRUE(test::valid_panels(r, panels, 0.1)) << (optimize ? "with" : "without") << " the fit";
  return measure_quality(r.mesh(), r.topology(), r.panels()).hausdorff;
}

TEST(OptimizePlanes, PanelsComeCloserToTheSurface) {
  const std::vector<FitCase> cases = {
      {"bunny 200", [] { return test::load_clean("bunny.off"); }, 200},
      {"inspired 100", [] { return test::load_clean("inspired_mesh.obj"); }, 100},
      {"saddle 120", [] { return make_saddle(8000); }, 120},
      {"bump 120", [] { return make_bump(8000); }, 120},
      {"roof with hole 120", [] { return make_roof_with_hole(8000); }, 120},
  };
  constexpr int kSeeds = 3;
  double log_ratio = 0.0;
  for (const FitCase& c : cases) {
    const TriMesh mesh = c.mesh();
    double case_log_ratio = 0.0;
    for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
      const double without = hausdorff(mesh, c.panels, seed, false);
      const double with = hausdorff(mesh, c.panels, seed, true);
      std::printf("%s seed %d: hausdorff %.5f without the fit, %.5f with it (%.2f)\n", c.name.c_str(),
                  static_cast<int>(seed), without, with, with / without);
      case_log_ratio += std::log(with / without);
    }
    EXPECT_LE(std::exp(case_log_ratio / kSeeds), 1.05) << c.name;
    log_ratio += case_log_ratio;
  }
  const double mean_ratio = std::exp(log_ratio / static_cast<double>(kSeeds * cases.size()));
  std::printf("geometric mean ratio %.3f\n", mean_ratio);
  EXPECT_LT(mean_ratio, 0.95);
}

}  // namespace
}  // namespace ff
