#pragma once
// Checks every Obstacle must pass at a point x, shared by the obstacles' tests: the normal is a
// unit vector, x - point = gap normal (the gap is the signed distance along the normal), and
// dNormal matches central differences of the normal in x.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <string>

#include "contact/Obstacle.hpp"

namespace glossa::contact::test {

inline void expectConsistentClosestPoint(const Obstacle &obstacle, const Eigen::Vector3d &x,
                                         const std::string &where) {
  const double search = 1e3;
  const auto cp = obstacle.closest(x, search);
  ASSERT_TRUE(cp) << where;
  EXPECT_NEAR(cp->normal.norm(), 1.0, 1e-14) << where;
  EXPECT_LT((x - cp->point - cp->gap * cp->normal).norm(), 1e-13 * (1 + x.norm())) << where;
  const double h = 1e-6;
  Eigen::Matrix3d fd;
  for (int j = 0; j < 3; ++j) {
    Eigen::Vector3d xp = x, xm = x;
    xp(j) += h;
    xm(j) -= h;
    fd.col(j) = (obstacle.closest(xp, search)->normal - obstacle.closest(xm, search)->normal) / (2 * h);
  }
  // The normal is smooth and O(1)-curved here: central differences are accurate to ~h^2.
  EXPECT_LT((cp->dNormal - fd).norm(), 1e-7 * (1 + cp->dNormal.norm())) << where;
}

}  // namespace glossa::contact::test
