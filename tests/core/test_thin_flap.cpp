// Issue 3: near-identical neighbouring planes let a node slide along their line, and a third
// panel folds back in a flap about 1e-6 wide that the star test passes. The panel check
// now calls such a corner a thin flap (panel_check.h fold_back_corners, the unit tests are
// in test_panel_check.cpp), so the solver mends it like any invalid panel. Here: the case
// it was found on, end to end, as `flatfacet remesh YasIsland.off --panels 150` runs it.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "core/panels/panel_check.h"
#include "core/prepare/prepare.h"
#include "core/quality/report.h"
#include "core/remesher.h"
#include "panel_checks.h"
#include "remesh_checks.h"
#include "test_meshes.h"

namespace ff {
namespace {

TEST(ThinFlap, YasIslandAt150PanelsHasNoFoldBackCorner) {
  const TriMesh yas = test::load_clean("YasIsland.off");
  const int panels = 150;
  PreparedSurface p = prepare_surface(yas, panels, {});
  RemeshParams params;
  params.panels = panels;
  Remesher r(std::move(p.mesh), params);
  r.run();
  EXPECT_TRUE(test::valid_panels(r, panels, 0.02));
  const PanelMesh& pm = r.panels();
  // Before the fix: a 0.0006 degree corner. A degree is far above it and far below the
  // sharpest corner a sound layout here has (2.9 degrees).
  const QualityReport q = measure_quality(r.mesh(), r.topology(), pm);
  EXPECT_GT(q.min_corner_angle_deg, 1.0);
  // And no fold-back corner narrower than 1e-4 of the panel's longest edge, checked here in
  // each panel's own plane, independently of the panel phase's flags.
  for (int k = 0; k < pm.num_panels(); ++k) {
    const std::vector<int>& panel = pm.panels[static_cast<size_t>(k)];
    const Vec3 normal = pm.plane_normals[static_cast<size_t>(k)];
    const PlaneFrame frame = make_plane_frame(pm.plane_offsets[static_cast<size_t>(k)] * normal, normal);
    std::vector<Vec2> polygon;
    double longest = 0.0;
    for (size_t i = 0; i < panel.size(); ++i) {
      polygon.push_back(frame.to_2d(pm.vertices[static_cast<size_t>(panel[i])]));
      longest = std::max(longest, (pm.vertices[static_cast<size_t>(panel[i])] -
                                   pm.vertices[static_cast<size_t>(panel[(i + 1) % panel.size()])])
                                      .norm());
    }
    EXPECT_TRUE(fold_back_corners(polygon, 1e-4 * longest, 1e-12 * longest).empty()) << "panel " << k;
  }
}

}  // namespace
}  // namespace ff
