// Probes (named points inside elements): on a box mesh bent by a smooth nonlinear map, so that
// its elements are trilinear and not affine, a point made from known local coordinates of a
// known element is found again, its weights are that element's shape functions there and they
// interpolate the point's own position; a point outside the mesh is not found.
#include <gtest/gtest.h>

#include <cmath>

#include "fem/HexShape.hpp"
#include "mesh/BoxGenerator.hpp"
#include "model/PointLocation.hpp"

using namespace glossa;

namespace {
mesh::HexMesh bentBox() {
  mesh::HexMesh m = mesh::generateBox(Eigen::Vector3d::Zero(), Eigen::Vector3d(1.0, 0.5, 0.4), {4, 3, 2});
  for (auto &x : m.nodes) x += Eigen::Vector3d(0.08 * std::sin(3.0 * x.y()), 0.05 * x.x() * x.x(), 0.04 * x.x() * x.y());
  return m;
}
} // namespace

TEST(PointLocation, FindsThePointsElementAndItsShapeFunctions) {
  const mesh::HexMesh m = bentBox();
  const mesh::ElementId e = 9;
  const Eigen::Vector3d xi(0.3, -0.6, 0.1);
  const Eigen::Matrix<double, 8, 3> X = m.elementCoordinates(e);
  const Eigen::Vector3d x = X.transpose() * fem::hexShape(xi);
  const auto at = model::locatePoint(m, x);
  ASSERT_TRUE(at.has_value());
  EXPECT_EQ(at->element, e);
  EXPECT_LT((at->xi - xi).norm(), 1e-12);
  const auto probe = model::probeAt(m, x);
  ASSERT_TRUE(probe.has_value());
  ASSERT_TRUE(probe->probe());
  Eigen::Vector3d back = Eigen::Vector3d::Zero();
  double sum = 0.0;
  for (const auto &[n, w] : probe->weights) {
    back += w * m.nodes[n];
    sum += w;
  }
  EXPECT_NEAR(sum, 1.0, 1e-14);
  EXPECT_LT((back - x).norm(), 1e-13);
  // interpolate() of the position field itself gives the point back.
  std::vector<double> positions;
  for (const auto &n : m.nodes) positions.insert(positions.end(), {n.x(), n.y(), n.z()});
  EXPECT_LT((probe->interpolate(positions) - x).norm(), 1e-13);
}

TEST(PointLocation, APointOutsideTheMeshIsNotFound) {
  const mesh::HexMesh m = bentBox();
  EXPECT_FALSE(model::locatePoint(m, Eigen::Vector3d(0.5, 0.25, 0.6)).has_value());
  EXPECT_FALSE(model::probeAt(m, Eigen::Vector3d(-0.2, 0.25, 0.2)).has_value());
}
