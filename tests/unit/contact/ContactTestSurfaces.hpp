#pragma once
// Small surfaces for the contact tests, with their geometry known in closed form, the
// central difference of a normal for the dNormal checks, and an unbounded closest-point query.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <functional>
#include <limits>
#include <vector>

#include "contact/TriangleSurface.hpp"
#include "contact/TriangulatedObstacle.hpp"

namespace glossa::contact::testing {

// |x| + |y| + |z| = 1, normals out: volume 4/3, each face at distance 1/sqrt(3) from 0.
inline TriangleSurface octahedron() {
  std::vector<Eigen::Vector3d> v = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<TriangleSurface::Triangle> t = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                              {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return TriangleSurface(std::move(v), std::move(t), {"octahedron", false, {}});
}

// The cube [0, 1]^3, normals out.
inline TriangleSurface unitCube() {
  std::vector<Eigen::Vector3d> v;
  for (int k = 0; k < 8; ++k) v.emplace_back(k & 1, (k >> 1) & 1, (k >> 2) & 1);
  std::vector<TriangleSurface::Triangle> t = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6},
                                              {0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3},
                                              {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return TriangleSurface(std::move(v), std::move(t), {"cube", false, {}});
}

// The open square [0, 1]^2 at z = 0 as two triangles, normals +z.
inline TriangleSurface unitSquareSheet() {
  std::vector<Eigen::Vector3d> v = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  return TriangleSurface(std::move(v), {{0, 1, 2}, {0, 2, 3}}, {"sheet", false, {}});
}

// A valley of two unit squares meeting along the y axis, rising to z = 1 at x = -1 and x = 1,
// normals up into the valley: its inner edge has two triangles on each side, its rim is free.
inline TriangleSurface valleySheet() {
  std::vector<Eigen::Vector3d> v = {{-1, 0, 1}, {0, 0, 0}, {0, 1, 0}, {-1, 1, 1}, {1, 0, 1}, {1, 1, 1}};
  std::vector<TriangleSurface::Triangle> t = {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}};
  return TriangleSurface(std::move(v), std::move(t), {"valley", false, {}});
}

// A sphere of radius R about c triangulated as an octahedron whose faces are cut into n x n
// triangles, every vertex then pushed onto the sphere; normals out. The triangles' corners lie on
// the sphere, so its exact normal (x - c)/|x - c| and gap |x - c| - R are the references the
// surface's normals are measured against.
inline TriangleSurface triangulatedSphere(int n, double R, const Eigen::Vector3d &c) {
  const TriangleSurface base = octahedron();
  std::vector<Eigen::Vector3d> v;
  std::vector<TriangleSurface::Triangle> t;
  // Vertices shared by neighbouring faces are merged by their (exact) grid coordinates on the
  // octahedron, before the projection.
  auto index = [&](const Eigen::Vector3d &p) {
    for (std::size_t k = 0; k < v.size(); ++k)
      if ((v[k] - p).norm() < 1e-12) return static_cast<int>(k);
    v.push_back(p);
    return static_cast<int>(v.size() - 1);
  };
  for (std::size_t f = 0; f < base.numTriangles(); ++f) {
    const Eigen::Vector3d a = base.corner(f, 0), b = base.corner(f, 1), d = base.corner(f, 2);
    auto at = [&](int i, int j) { return index(a + (b - a) * i / double(n) + (d - a) * j / double(n)); };
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        t.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
        if (i + j + 1 < n) t.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
  }
  for (Eigen::Vector3d &p : v) p = c + R * p.normalized();
  return TriangleSurface(std::move(v), std::move(t), {"sphere", false, {}});
}

// d normal / d x by central differences, column j the derivative along e_j.
inline Eigen::Matrix3d centralDifference(
    const std::function<Eigen::Vector3d(const Eigen::Vector3d &)> &normal, const Eigen::Vector3d &x,
    double h) {
  Eigen::Matrix3d D;
  for (int j = 0; j < 3; ++j) {
    const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(j);
    D.col(j) = (normal(x + e) - normal(x - e)) / (2 * h);
  }
  return D;
}

// The obstacle's answer at x with no search radius; a test failure if it gives none.
inline ClosestPoint queryAnywhere(const TriangulatedObstacle &o, const Eigen::Vector3d &x) {
  const auto cp = o.closest(x, std::numeric_limits<double>::infinity());
  EXPECT_TRUE(cp.has_value());
  return cp ? *cp : ClosestPoint{};
}

}  // namespace glossa::contact::testing
