#pragma once
// Faces and checks shared by the contact kernel's tests: rectangles and uniform displacements,
// the total of nodal forces, the tangent against central differences of the forces (at fixed
// multipliers and anchors), random warping (RandomFaces).

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

#include "RandomFaces.hpp"
#include "contact/FaceContact.hpp"

namespace glossa::contact::test {

using glossa::loads::FaceForces;
using glossa::loads::FaceNodes;
using glossa::loads::FaceTangent;

// The bottom face of a body resting on z = 0, in the outward (downward) right-hand node order.
inline FaceNodes rectangle(double a, double b) {
  FaceNodes X;
  X << 0, 0, 0, 0, b, 0, a, b, 0, a, 0, 0;
  return X;
}
inline FaceNodes uniform(const Eigen::Vector3d &v) {
  FaceNodes u;
  for (int a = 0; a < 4; ++a) u.row(a) = v.transpose();
  return u;
}
inline Eigen::Vector3d total(const FaceForces &f) {
  return f.segment<3>(0) + f.segment<3>(3) + f.segment<3>(6) + f.segment<3>(9);
}

// K against central differences of f. Returns how many points are active.
inline int expectTangentMatchesCentralDifferences(const Obstacle &obstacle, const FaceNodes &X, const FaceNodes &u,
                                           const FaceMultipliers &lambda, const ContactSettings &settings,
                                           const std::string &where, const FaceAnchors *anchors = nullptr) {
  FaceContactPoints points;
  FaceTangent K;
  faceContactForces(obstacle, X, u, lambda, settings, &points, &K, anchors);
  const int active = static_cast<int>(
      std::count_if(points.begin(), points.end(), [](const ContactPointState &p) { return p.active(); }));
  const double h = 1e-6;
  FaceTangent Kfd;
  for (int b = 0; b < 4; ++b)
    for (int j = 0; j < 3; ++j) {
      FaceNodes up = u, um = u;
      up(b, j) += h;
      um(b, j) -= h;
      Kfd.col(3 * b + j) = (faceContactForces(obstacle, X, up, lambda, settings, nullptr, nullptr, anchors) -
                            faceContactForces(obstacle, X, um, lambda, settings, nullptr, nullptr, anchors)) /
                           (2 * h);
    }
  if (active > 0) {
    EXPECT_LT((K - Kfd).norm(), 1e-6 * K.norm()) << where;
  } else {
    EXPECT_EQ(K.norm(), 0.0) << where;
    EXPECT_EQ(Kfd.norm(), 0.0) << where;
  }
  return active;
}

using glossa::test::perturbed;

}  // namespace glossa::contact::test
