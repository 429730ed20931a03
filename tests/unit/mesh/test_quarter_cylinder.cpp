// generateQuarterCylinder, the O-grid quarter of a solid cylinder graded towards its lowest line,
// against its closed-form geometry: every arc node on the circle, the planes exact, a valid
// conforming mesh whose sets are the whole boundary, the fine band as asked, and a cross-section
// area that converges to pi R^2 / 4 at second order when every count doubles.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "MeshTestChecks.hpp"
#include "mesh/MeshChecks.hpp"
#include "mesh/MeshQuality.hpp"
#include "mesh/QuarterCylinderGenerator.hpp"

namespace glossa::mesh {
namespace {

constexpr double kR = 2.0, kH = 0.5, kBand = 0.3;

// The x of the arc's nodes in the plane z = 0, sorted: where contact points sit along the surface.
std::vector<double> arcAbscissae(const HexMesh &mesh) {
  std::vector<double> x;
  for (NodeId v : mesh.nodeSet("arc"))
    if (mesh.nodes[v].z() == 0.0) x.push_back(mesh.nodes[v].x());
  std::sort(x.begin(), x.end());
  return x;
}

TEST(QuarterCylinder, CountsCircleAndPlanes) {
  const QuarterCylinderCells c{4, 2, 3, 5, 2};
  const HexMesh mesh = generateQuarterCylinder(kR, kH, c, kBand);
  const int na = c.band + c.contact;
  EXPECT_EQ(mesh.numElements(), static_cast<std::size_t>((na * c.side + (na + c.side) * c.radial) * c.axial));
  // Per layer: the inner square's grid, and the two outer blocks less the nodes they share with it
  // and with each other (the 45 degree ray).
  const int perLayer = (na + 1) * (c.side + 1) + (na + c.side + 1) * c.radial;
  EXPECT_EQ(mesh.numNodes(), static_cast<std::size_t>(perLayer * (c.axial + 1)));
  const Eigen::Vector3d axis(0.0, kR, 0.0);
  for (NodeId v : mesh.nodeSet("arc")) {
    const Eigen::Vector3d d = mesh.nodes[v] - axis;
    EXPECT_NEAR(std::hypot(d.x(), d.y()), kR, 1e-14 * kR);
  }
  EXPECT_EQ(mesh.faceSet("arc").size(), static_cast<std::size_t>((na + c.side) * c.axial));
  EXPECT_EQ(mesh.faceSet("x0").size(), static_cast<std::size_t>((c.side + c.radial) * c.axial));
  EXPECT_EQ(mesh.faceSet("top").size(), static_cast<std::size_t>((na + c.radial) * c.axial));
  for (NodeId v : mesh.nodeSet("x0")) EXPECT_EQ(mesh.nodes[v].x(), 0.0);
  for (NodeId v : mesh.nodeSet("top")) EXPECT_EQ(mesh.nodes[v].y(), kR);
  for (NodeId v : mesh.nodeSet("zmax")) EXPECT_EQ(mesh.nodes[v].z(), kH);
  std::size_t inSets = 0;
  for (const auto &[name, faces] : mesh.faceSets) {
    inSets += faces.size();
    testing::expectOutwardNormals(mesh, name);
  }
  EXPECT_EQ(inSets, boundaryFaces(mesh).size());
  EXPECT_EQ(mesh.namedPoints.at("lowest").position, Eigen::Vector3d(0.0, 0.0, 0.0));
  EXPECT_EQ(mesh.namedPoints.at("axis").position, axis);
}

TEST(QuarterCylinder, ValidConformingMesh) {
  for (double band : {0.05 * kR, 0.6 * kR}) {
    SCOPED_TRACE(band);
    // The rays meet the inner square's sides at 45 degrees at worst.
    testing::expectValidConformingMesh(generateQuarterCylinder(kR, kH, {8, 8, 4, 12, 1}, band), 0.7);
  }
}

// Along the arc, equal cells (in angle) up to x = band, then growing to 45 degrees; the first cell
// along the ray straight down is as long as a band cell is along the arc.
TEST(QuarterCylinder, FineBandAtTheLowestLine) {
  const int band = 6, rest = 10;
  const HexMesh mesh = generateQuarterCylinder(kR, kH, {band, rest, 4, 12, 1}, kBand);
  const auto angle = [&](double x) { return std::asin(x / kR); };
  const auto x = arcAbscissae(mesh);
  const double cell = angle(kBand) / band;
  for (int i = 0; i < band; ++i) EXPECT_NEAR(angle(x[i + 1]) - angle(x[i]), cell, 1e-12) << i;
  EXPECT_NEAR(x[band], kBand, 1e-14 * kR);
  EXPECT_NEAR(angle(x[band + 1]) - angle(x[band]), cell, 1e-9);
  for (int i = band + 1; i < band + rest; ++i)
    EXPECT_GT(angle(x[i + 1]) - angle(x[i]), angle(x[i]) - angle(x[i - 1])) << "grows past the band, " << i;
  EXPECT_NEAR(angle(x[band + rest]), 0.25 * M_PI, 1e-14);
  // The nodes on x = 0 below the inner square, nearest the lowest point first.
  std::vector<double> y;
  for (NodeId v : mesh.nodeSet("x0"))
    if (mesh.nodes[v].z() == 0.0) y.push_back(mesh.nodes[v].y());
  std::sort(y.begin(), y.end());
  EXPECT_EQ(y[0], 0.0);
  EXPECT_NEAR(y[1] - y[0], kR * cell, 1e-9 * kR * cell);
  EXPECT_GT(y[2] - y[1], y[1] - y[0]);
}

TEST(QuarterCylinder, AreaConvergesAtSecondOrder) {
  const double exact = 0.25 * M_PI * kR * kR * kH;
  double previous = 0.0;
  for (int k : {1, 2, 4}) {
    // Straight chords between arc nodes: the error is the segments cut off, O(h^2).
    const double error =
        std::abs(meshVolume(generateQuarterCylinder(kR, kH, {4 * k, 4 * k, 2 * k, 4 * k, 1}, kBand)) / exact - 1.0);
    std::printf("counts x %d: area error %.3e\n", k, error);
    if (previous > 0.0) {
      EXPECT_NEAR(previous / error, 4.0, 0.4) << k;
    }
    previous = error;
  }
  EXPECT_LT(previous, 2e-3);
}

TEST(QuarterCylinder, RefusesBadArguments) {
  const QuarterCylinderCells c;
  EXPECT_THROW(generateQuarterCylinder(0.0, kH, c, kBand), std::invalid_argument);
  EXPECT_THROW(generateQuarterCylinder(INFINITY, kH, c, kBand), std::invalid_argument);
  EXPECT_THROW(generateQuarterCylinder(kR, 0.0, c, kBand), std::invalid_argument);
  EXPECT_THROW(generateQuarterCylinder(kR, kH, c, 0.0), std::invalid_argument);
  EXPECT_THROW(generateQuarterCylinder(kR, kH, c, 0.75 * kR), std::invalid_argument); // past 45 degrees
  EXPECT_THROW(generateQuarterCylinder(kR, kH, c, NAN), std::invalid_argument);
  for (int i = 0; i < 5; ++i) {
    QuarterCylinderCells bad;
    (i == 0 ? bad.band : i == 1 ? bad.contact : i == 2 ? bad.side : i == 3 ? bad.radial : bad.axial) = 0;
    EXPECT_THROW(generateQuarterCylinder(kR, kH, bad, kBand), std::invalid_argument) << i;
  }
}

} // namespace
} // namespace glossa::mesh
