#pragma once
// A model cut by symmetry planes (the thick sphere's octant, the blocks of §7.1) stands for the
// whole body with its mirror images, which lie on the far side of each plane. A state in which
// material has crossed a plane overlaps its own mirror image: the body has passed through itself,
// although every element may be sound (the thick sphere past its maximum, its inner wall through
// the centre into another octant with the smallest Gauss-point J 0.83). Such an inside-out state
// is refused after each converged step (doc/theory.md, "Inside-out states").
//
// A Dirichlet condition acts as a symmetry plane when it fixes exactly one component c, to zero
// (no expression), all its nodes lie on one plane X_c = const, and every node of the mesh lies on
// one side of that plane in the reference configuration.

#include <cstddef>
#include <vector>

#include "mesh/HexMesh.hpp"
#include "model/Scene.hpp"

namespace glossa::model {

struct SymmetryPlane {
  std::size_t condition; // index in Scene::dirichlet
  int axis;              // c: the plane is X_c = position
  double position;       // [m]
  double side;           // +1 or -1: the side the body lies on
};

std::vector<SymmetryPlane> findSymmetryPlanes(const mesh::HexMesh &mesh, const std::vector<DirichletCondition> &conditions);

// The node farthest across any plane: its signed distance side (x_c - position), negative when
// across, at displacement u (3 per mesh node). distance = +infinity when there are no planes.
struct PlaneCrossing {
  double distance;
  mesh::NodeId node;
  std::size_t plane; // index in the planes
};
PlaneCrossing deepestCrossing(const std::vector<SymmetryPlane> &planes, const mesh::HexMesh &mesh,
                              const std::vector<double> &u);

} // namespace glossa::model
