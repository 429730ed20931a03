#include "model/SymmetryPlanes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace glossa::model {

namespace {
double meshExtent(const mesh::HexMesh &mesh) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto &x : mesh.nodes) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  return mesh.nodes.empty() ? 0.0 : (hi - lo).maxCoeff();
}
} // namespace

std::vector<SymmetryPlane> findSymmetryPlanes(const mesh::HexMesh &mesh, const std::vector<DirichletCondition> &conditions) {
  std::vector<SymmetryPlane> planes;
  const double tolerance = 1e-9 * meshExtent(mesh);
  for (std::size_t b = 0; b < conditions.size(); ++b) {
    const DirichletCondition &bc = conditions[b];
    if (bc.elastic() || bc.nodes.empty() || std::count(bc.fixed.begin(), bc.fixed.end(), true) != 1) continue;
    const int c = static_cast<int>(std::find(bc.fixed.begin(), bc.fixed.end(), true) - bc.fixed.begin());
    if (bc.expression[c] || bc.value[c] != 0.0) continue;
    const double position = mesh.nodes[bc.nodes.front()][c];
    const bool planar = std::all_of(bc.nodes.begin(), bc.nodes.end(),
                                    [&](mesh::NodeId n) { return std::abs(mesh.nodes[n][c] - position) <= tolerance; });
    if (!planar) continue;
    double below = 0.0, above = 0.0;
    for (const auto &x : mesh.nodes) below = std::min(below, x[c] - position), above = std::max(above, x[c] - position);
    if (below < -tolerance && above > tolerance) continue; // the body on both sides: not a symmetry plane
    planes.push_back({b, c, position, above > tolerance ? 1.0 : -1.0});
  }
  return planes;
}

PlaneCrossing deepestCrossing(const std::vector<SymmetryPlane> &planes, const mesh::HexMesh &mesh,
                              const std::vector<double> &u) {
  PlaneCrossing deepest{std::numeric_limits<double>::infinity(), 0, 0};
  for (std::size_t p = 0; p < planes.size(); ++p) {
    const SymmetryPlane &plane = planes[p];
    for (std::size_t n = 0; n < mesh.numNodes(); ++n) {
      const double d = plane.side * (mesh.nodes[n][plane.axis] + u[3 * n + static_cast<std::size_t>(plane.axis)] - plane.position);
      if (d < deepest.distance) deepest = {d, static_cast<mesh::NodeId>(n), p};
    }
  }
  return deepest;
}

} // namespace glossa::model
