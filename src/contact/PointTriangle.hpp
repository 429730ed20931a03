#pragma once
// The closest point of one triangle to a point, and which feature of the triangle it lies on
// (the interior, one of the three edges, one of the three corners): the contact normal differs
// between them (doc/contact.md, "Search").

#include <Eigen/Core>

namespace glossa::contact {

struct TriangleProjection {
  enum class Feature { Face, Edge, Vertex };
  Eigen::Vector3d point;
  Feature feature = Feature::Face;
  // Edge k runs from corner k to corner (k + 1) % 3; for a vertex, the corner's index.
  int index = 0;
};

// Ericson, Real-Time Collision Detection (2005), sec. 5.1.5: the Voronoi region of x among the
// triangle's corners, edges and interior, decided on the signs of the same dot products that
// give the point, so the feature and the point always agree.
TriangleProjection closestOnTriangle(const Eigen::Vector3d &x, const Eigen::Vector3d &a,
                                     const Eigen::Vector3d &b, const Eigen::Vector3d &c);

}  // namespace glossa::contact
