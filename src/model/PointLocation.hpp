#pragma once
// Where a point lies in a hexahedral mesh: the element containing it and the point's local
// coordinates there, found by Newton's method on the element's trilinear map (for a probe:
// output at a point that is no mesh node, interpolated in its element). Eigen only.

#include <optional>

#include <Eigen/Core>

#include "mesh/HexMesh.hpp"

namespace glossa::model {

struct ElementPoint {
  mesh::ElementId element = 0;
  Eigen::Vector3d xi = Eigen::Vector3d::Zero(); // in [-1, 1]^3
};

// The first element (in id order) whose closure holds x, to `tolerance` in the local
// coordinates; nullopt outside the mesh. Elements whose bounding box misses x are skipped.
std::optional<ElementPoint> locatePoint(const mesh::HexMesh &mesh, const Eigen::Vector3d &x, double tolerance = 1e-10);

// The named point at x: a probe with its element's nodes and shape functions at x, its `node`
// the element's node nearest x. nullopt outside the mesh.
std::optional<mesh::NamedPoint> probeAt(const mesh::HexMesh &mesh, const Eigen::Vector3d &x);

} // namespace glossa::model
