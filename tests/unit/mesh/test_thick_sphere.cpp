// generateThickSphere, the cubed-sphere octant of a spherical shell, against its closed-form
// geometry: counts, radii and symmetry planes exact, a valid conforming mesh, outward faces, and
// a volume that converges to pi/6 (b^3 - a^3) at second order.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "MeshTestChecks.hpp"
#include "mesh/MeshChecks.hpp"
#include "mesh/MeshQuality.hpp"
#include "mesh/ThickSphereGenerator.hpp"

namespace glossa::mesh {
namespace {

constexpr double kA = 1.0, kB = 2.0;

TEST(ThickSphere, CountsRadiiAndPlanes) {
  const int m = 3, n = 4;
  const HexMesh mesh = generateThickSphere(kA, kB, m, n);
  EXPECT_EQ(mesh.numElements(), static_cast<std::size_t>(3 * n * n * m));
  // Per layer the octant's surface grid: three (n+1)^2 patches, sharing three edges and a corner.
  EXPECT_EQ(mesh.numNodes(), static_cast<std::size_t>((3 * n * n + 3 * n + 1) * (m + 1)));
  for (NodeId v : mesh.nodeSet("inner")) EXPECT_NEAR(mesh.nodes[v].norm(), kA, 1e-14);
  for (NodeId v : mesh.nodeSet("outer")) EXPECT_NEAR(mesh.nodes[v].norm(), kB, 1e-14);
  for (int d = 0; d < 3; ++d) {
    const std::string plane = std::string(1, "xyz"[d]) + "0";
    // (n+1) nodes along each layer's arc of the plane, exactly on it.
    EXPECT_EQ(mesh.nodeSet(plane).size(), static_cast<std::size_t>((2 * n + 1) * (m + 1))) << plane;
    for (NodeId v : mesh.nodeSet(plane)) EXPECT_EQ(mesh.nodes[v](d), 0.0) << plane;
    EXPECT_EQ(mesh.faceSet(plane).size(), static_cast<std::size_t>(2 * n * m)) << plane;
  }
  EXPECT_EQ(mesh.faceSet("inner").size(), static_cast<std::size_t>(3 * n * n));
  EXPECT_EQ(mesh.faceSet("outer").size(), static_cast<std::size_t>(3 * n * n));
  // The five sets are the whole boundary.
  std::size_t inSets = 0;
  for (const auto &[name, faces] : mesh.faceSets) inSets += faces.size();
  EXPECT_EQ(inSets, boundaryFaces(mesh).size());
  for (const auto &[name, faces] : mesh.faceSets) testing::expectOutwardNormals(mesh, name);
  EXPECT_EQ((mesh.namedPoints.at("inner").position - Eigen::Vector3d(kA, 0, 0)).norm(), 0.0);
  EXPECT_EQ((mesh.namedPoints.at("outer").position - Eigen::Vector3d(kB, 0, 0)).norm(), 0.0);
}

TEST(ThickSphere, ValidConformingMesh) {
  // Equal angles keep the cells near-cubic.
  testing::expectValidConformingMesh(generateThickSphere(kA, kB, 4, 6), 0.5);
}

TEST(ThickSphere, VolumeConvergesAtSecondOrder) {
  const double exact = M_PI / 6.0 * (kB * kB * kB - kA * kA * kA);
  double previous = 0.0;
  for (int n : {4, 8, 16}) {
    // Radial layers are straight in r, so only the surface faceting errs.
    const double error = std::abs(meshVolume(generateThickSphere(kA, kB, 2, n)) / exact - 1.0);
    std::printf("n = %d: volume error %.3e\n", n, error);
    if (previous > 0.0) {
      EXPECT_NEAR(previous / error, 4.0, 0.6) << "n = " << n;
    }
    previous = error;
  }
  EXPECT_LT(previous, 2e-3);
}

TEST(ThickSphere, RefusesBadArguments) {
  EXPECT_THROW(generateThickSphere(0.0, 1.0, 1, 1), std::invalid_argument);
  EXPECT_THROW(generateThickSphere(2.0, 1.0, 1, 1), std::invalid_argument);
  EXPECT_THROW(generateThickSphere(1.0, INFINITY, 1, 1), std::invalid_argument);
  EXPECT_THROW(generateThickSphere(1.0, 2.0, 0, 1), std::invalid_argument);
  EXPECT_THROW(generateThickSphere(1.0, 2.0, 1, 0), std::invalid_argument);
}

} // namespace
} // namespace glossa::mesh
