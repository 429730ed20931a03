// The segmented slave points (contact/SlaveSegments): the cells the master faces' edges cut a
// slave face into cover it exactly (weights sum to its area), no cell straddles a master edge, and
// the master's nodal forces of a uniform pressure integrated with them are exact where a Gauss rule
// is not: int N_b^m over the slave face, against the closed-form overlap areas.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>

#include "contact/SlaveSegments.hpp"
#include "loads/FaceShape.hpp"

using namespace glossa::contact;
using glossa::loads::FaceNodes;

namespace {
// The rectangle [x0, x1] x [y0, y1] at z, right-hand normal +z (up) or -z.
FaceNodes rectangle(double x0, double x1, double y0, double y1, double z, bool up) {
  FaceNodes X;
  if (up)
    X << x0, y0, z, x1, y0, z, x1, y1, z, x0, y1, z;
  else
    X << x0, y0, z, x0, y1, z, x1, y1, z, x1, y0, z;
  return X;
}

// int over the slave face of the master face's shape function of node b (the master's nodal force
// of a unit pressure), with the given points; each point is projected onto the master face and
// counts only inside it.
double masterLoad(const FaceNodes &slave, const FaceNodes &master, const std::vector<SlavePoint> &points,
                  int b) {
  double sum = 0.0;
  for (const SlavePoint &q : points) {
    const auto sh = glossa::loads::faceShape(q.st(0), q.st(1));
    const Eigen::Vector3d x = slave.transpose() * sh.N;
    const double j = (slave.transpose() * sh.dNds).cross(slave.transpose() * sh.dNdt).norm();
    const auto p = projectOntoFace(master, x);
    if (!p || !p->inside) continue;
    sum += q.weight * j * glossa::loads::faceShape(p->st(0), p->st(1)).N(b);
  }
  return sum;
}
}  // namespace

TEST(SlaveSegments, CellsCoverTheFaceAndIntegrateTheMastersShapeFunctionsExactly) {
  // A slave face [0, 0.43] x [0.18, 0.71] over a uniform master grid of quarters (both at z = 0).
  const FaceNodes slave = rectangle(0.0, 0.43, 0.18, 0.71, 0.0, false);
  std::vector<FaceNodes> masters;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      masters.push_back(rectangle(0.25 * i, 0.25 * (i + 1), 0.25 * j, 0.25 * (j + 1), 0.0, true));
  const std::vector<SlavePoint> points = segmentedSlavePoints(slave, masters);
  double area = 0.0;
  for (const SlavePoint &q : points) area += q.weight;
  EXPECT_NEAR(area, 4.0, 1e-13);
  // The master face [0.25, 0.5] x [0.5, 0.75]: its node 0 at (0.25, 0.5). The overlap with the slave
  // is [0.25, 0.43] x [0.5, 0.71]; int N_0 there = int (0.5 - x)/0.25 dx * int (0.75 - y)/0.25 dy.
  const FaceNodes &m = masters[1 * 4 + 2];
  auto hat = [](double a, double b, double far) { return (far * (b - a) - 0.5 * (b * b - a * a)) / 0.25; };
  const double exact = hat(0.25, 0.43, 0.5) * hat(0.5, 0.71, 0.75);
  EXPECT_NEAR(masterLoad(slave, m, points, 0), exact, 1e-14);
  // The 2 x 2 Gauss rule misses it: the master's kinks lie inside the slave face.
  const double gauss = masterLoad(slave, m, slavePoints(2), 0);
  EXPECT_GT(std::abs(gauss - exact), 1e-4 * exact);
  std::printf(
      "int N_0 of a master face over a slave face: exact %.6e, segments %.3e off, 2x2 Gauss %.3e off\n",
      exact, std::abs(masterLoad(slave, m, points, 0) - exact), std::abs(gauss - exact));
}
