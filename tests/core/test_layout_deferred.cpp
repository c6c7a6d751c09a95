// A PanelLayout built with build_panels = false (the panel attempt's layouts, whose planes the
// relaxation replaces at once) must end, after set_planes(), exactly (bit for bit) as one
// that built its panels in the constructor and then rebuilt those the new planes reach:
// where some planes moved, where none did, and with every plane moved.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "bunny_attempt.h"
#include "core/panels/panel_layout.h"

namespace ff {
namespace {

// The panels, and the nodes the next relaxation reads.
void expect_same_layout(const PanelLayout& a, const PanelLayout& b) {
  test::expect_same_panels(a, b);
  const std::vector<NodeConstraint> m = a.node_constraints(), n = b.node_constraints();
  ASSERT_EQ(m.size(), n.size());
  EXPECT_EQ(a.spike_nodes(), b.spike_nodes());
}

// test::BunnyAttempt, and layouts on its clusters with masters of our choosing.
struct Bunny : test::BunnyAttempt {
  LayoutOptions options;

  Bunny() {
    options.diameter = diameter;
    options.spike_distance = 0.2 * diameter;
  }
  std::unique_ptr<PanelLayout> layout(const MasterPlanes& planes, bool build) const {
    return std::make_unique<PanelLayout>(mesh, topology, attempt->clustering().labels, positions, attempt->graph(),
                                         planes, options, std::vector<std::pair<int, int>>{}, build);
  }
};

TEST(LayoutDeferred, SetPlanesBuildsAsTheConstructorAndARebuild) {
  const Bunny b;
  const MasterPlanes relaxed = b.attempt->layout().planes();
  // The constructor's planes: two masters in three moved off the relaxed ones.
  MasterPlanes start = relaxed;
  for (size_t m = 0; m < start.planes.size(); ++m) start.planes[m].offset += 1e-3 * static_cast<double>(m % 3);
  const std::vector<const std::vector<Plane>*> targets = {&relaxed.planes, &start.planes};
  for (const std::vector<Plane>* target : targets) {
    auto built = b.layout(start, true);
    auto deferred = b.layout(start, false);
    built->set_planes(*target);
    deferred->set_planes(*target);
    expect_same_layout(*built, *deferred);
    // And the layout goes on as usual: another change rebuilds what it reaches, the same way.
    std::vector<Plane> moved = *target;
    moved[0].offset += 2e-3;
    built->set_planes(moved);
    deferred->set_planes(moved);
    expect_same_layout(*built, *deferred);
  }
  // Some panels are invalid on these planes: the comparison covers the checks' flags too.
  auto built = b.layout(start, true);
  EXPECT_GT(built->num_invalid(), 0);
}

}  // namespace
}  // namespace ff
