#include "core/fabricate/solid_panels.h"

#include <cstdio>

#include "core/fabricate/parts_list.h"

namespace ff {

std::string solid_panels_obj(const PanelMesh& pm, double thickness, MaterialSide side) {
  ThickOptions options;
  options.thickness = thickness;
  options.side = side;
  return solid_panels_obj(pm, options, 1.0, "");
}

std::string solid_panels_obj(const PanelMesh& pm, const ThickOptions& options, double scale, const std::string& units) {
  const MaterialSide side = options.side;
  const ThickPanels thick = thicken_panels(pm, panel_edges(pm), options);
  const std::vector<PanelPart> parts = panel_parts(pm);
  std::string obj = "# flatfacet solid panels: outer face, inner face, edge cuts; one object per panel\n";
  if (!units.empty()) obj += "# units: " + units + "\n";
  char buf[128];
  long base = 1;
  for (size_t p = 0; p < pm.panels.size(); ++p) {
    const std::vector<int>& poly = pm.panels[p];
    const long k = static_cast<long>(poly.size());
    obj += "o " + parts[p].label + "\n";
    for (const int v : poly) {
      const Vec3 x = pm.vertices[static_cast<size_t>(v)] * scale;
      std::snprintf(buf, sizeof buf, "v %.17g %.17g %.17g\n", x.x(), x.y(), x.z());
      obj += buf;
    }
    for (const Vec3& inner : thick.inner[p]) {
      const Vec3 x = inner * scale;
      std::snprintf(buf, sizeof buf, "v %.17g %.17g %.17g\n", x.x(), x.y(), x.z());
      obj += buf;
    }
    // The outer face keeps the panel's orientation when the material is behind it; the
    // other face is reversed, so every face points out of the solid.
    const bool inside = side == MaterialSide::Inside;
    std::string outer = "f", inner = "f";
    for (long i = 0; i < k; ++i) {
      outer += " " + std::to_string(base + (inside ? i : k - 1 - i));
      inner += " " + std::to_string(base + k + (inside ? k - 1 - i : i));
    }
    obj += outer + "\n" + inner + "\n";
    for (long i = 0; i < k; ++i) {
      const long a = base + i, b = base + (i + 1) % k;
      // Outer edge a -> b runs counter-clockwise around the outward normal: the side quad
      // goes b -> a on the outer face, then down to the inner face.
      if (inside)
        std::snprintf(buf, sizeof buf, "f %ld %ld %ld %ld\n", b, a, a + k, b + k);
      else
        std::snprintf(buf, sizeof buf, "f %ld %ld %ld %ld\n", a, b, b + k, a + k);
      obj += buf;
    }
    base += 2 * k;
  }
  return obj;
}

}  // namespace ff
