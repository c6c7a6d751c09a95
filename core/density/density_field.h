#pragma once
// Where the designer's size and direction controls meet the clustering (paper 3.3): a
// procedural density expression (expression.h) evaluated per vertex, multiplied with a painted
// density, and the anisotropy directions (anisotropy.h), all baked into the FaceData the
// metric reads. Curvature is estimated only when the expression or the direction needs it.
#include <string>
#include <vector>

#include "core/cluster/face_data.h"
#include "core/density/anisotropy.h"
#include "core/density/expression.h"
#include "core/mesh/curvature.h"
#include "core/mesh/topology.h"
#include "core/mesh/tri_mesh.h"

namespace ff {

// The expression at every vertex (inputs as documented in expression.h). `curvature` must be
// given when expression.uses_curvature(). Throws InputError naming the first vertex (and its
// position) where the value is not finite and > 0, or when the values span more than a factor
// 1e6 (such a field could only overflow the metric).
std::vector<double> expression_density(const TriMesh& mesh, const MeshTopology& topology, const Expression& expression,
                                       const VertexCurvature* curvature);

// The same from the expression's text, the topology and curvature (when it needs it) built
// here: what the preparation sizes by (PrepareOptions::sizing_density) before the Remesher
// evaluates the expression on the prepared mesh. Throws InputError as above, and for an
// expression that does not parse.
std::vector<double> expression_density(const TriMesh& mesh, const std::string& expression);

// FaceData for the Remesher. `painted`: empty, per vertex or per face (make_face_data);
// `expression`: empty for none, else parsed and evaluated per vertex and multiplied in (a
// per-face painted value takes the mean of its corners' expression values).
FaceData make_shaped_face_data(const TriMesh& mesh, const MeshTopology& topology, const std::vector<double>& painted,
                               const std::string& expression, const Anisotropy& anisotropy);

}  // namespace ff
