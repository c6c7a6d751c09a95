#pragma once
// The boundary term (paper 3.2, fifth metric), for the Lloyd rounds of the panel phase: a
// face's centroid projected onto a cluster's plane costs nothing inside that cluster's panel
// and, outside it, its distance to the panel's boundary, times the face's area and the
// designer's weight (so it compares with the other terms, which are areas too), over a
// length unit of D / 50. That unit is what makes it work: the euclidean term resists a
// boundary shift by about (shift / D) * area, so with D itself as the unit, clusters settle
// halfway between their Voronoi shape and their panel and the corners never reach the
// nodes. At D / 50, a face lying under a neighbour's panel moves to it, so the clusters (and
// their corners) follow the panels, which is the fixed point the panel phase looks for.
#include <vector>

#include "core/cluster/flood.h"
#include "core/panels/panel_layout.h"
#include "core/panels/polygon2d.h"

namespace ff {

class BoundaryTerm : public ExtraCost {
 public:
  // Clusters without a polygon (not disks) add nothing.
  BoundaryTerm(const FaceData& faces, const PanelLayout& layout, double weight, double diameter);
  static constexpr double kLengthUnit = 1.0 / 50.0;  // of D
  double operator()(int face, int cluster) const override;
  int fixed_label(int face) const override;
  // The cluster adds nothing (its panel no longer matches it).
  void ignore(int cluster);
  // Settled clusters keep exactly their faces (labels: the current ones): any other
  // assignment to or from them costs kForbidden, so the flood leaves them as they are.
  void freeze(const std::vector<char>& settled, const std::vector<int>& labels);
  static constexpr double kForbidden = 1e30;

 private:
  const FaceData& faces_;
  std::vector<PlaneFrame> frames_;
  std::vector<std::vector<Vec2>> polygons_;
  double scale_;  // weight / (kLengthUnit D)
  std::vector<char> settled_;
  std::vector<int> labels_;
};

}  // namespace ff
