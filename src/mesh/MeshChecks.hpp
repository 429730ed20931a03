#pragma once
// What a mesh must not hold before a run, found on the whole (replicated) mesh so that every
// rank count gives the same answer. Each of these passed the importers' Gauss-point check and
// then failed deep in the linear algebra or ran on a wrong body:
//  - a node no element uses (no stiffness: a singular system on one rank, a "converged" run on
//    two);
//  - two nodes at the same place (elements that look joined and are not, or a collapsed edge);
//  - two elements on the same eight nodes (a duplicate, counted twice in mass and stiffness);
//  - a corner whose scaled Jacobian is <= 0 (an inverted or degenerate corner the 2x2x2 Gauss
//    points do not see).
// The scene check that uses these (input/SceneChecks.hpp) decides which are refused and which
// a deck may allow. Eigen only.

#include <cstddef>
#include <utility>
#include <vector>

#include "mesh/HexMesh.hpp"

namespace glossa::mesh {

struct InvertedCorner {
  ElementId element;
  double scaledJacobian; // the element's smallest corner (or centre) value
};

struct MeshCheckReport {
  std::vector<NodeId> unusedNodes;                          // sorted
  std::vector<std::pair<NodeId, NodeId>> coincidentNodes;   // (lower, higher), sorted
  std::vector<std::pair<ElementId, ElementId>> duplicateElements; // (first, later)
  std::vector<InvertedCorner> invertedCorners;              // scaled Jacobian <= 0, by element
};

// Two nodes are coincident when closer than `relativeTolerance` times the shortest element edge
// of the mesh (an exact duplicate and a rounding-level one are both found; neighbours of a
// graded mesh are not).
MeshCheckReport checkMesh(const HexMesh &mesh, double relativeTolerance = 1e-6);

// The connected parts of the mesh: for each element, the index of its part (elements sharing a
// node are in one part), and the number of parts.
std::pair<std::vector<int>, int> meshParts(const HexMesh &mesh);

} // namespace glossa::mesh
