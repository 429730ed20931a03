// generateCookMembrane against the trapezoid's closed-form geometry.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "MeshTestChecks.hpp"
#include "mesh/CookMembraneGenerator.hpp"
#include "mesh/HexMesh.hpp"
#include "mesh/MeshQuality.hpp"

namespace glossa::mesh {
namespace {

const std::array<std::string, 6> kSides = {"clamped", "loaded", "bottom", "top", "front", "back"};

// The membrane's corners [mm], counter-clockwise.
const std::array<Eigen::Vector2d, 4> kCorners = {Eigen::Vector2d(0, 0), Eigen::Vector2d(48, 44),
                                                 Eigen::Vector2d(48, 60), Eigen::Vector2d(0, 44)};

// Shoelace formula: A = 1/2 |sum_i (x_i y_{i+1} - x_{i+1} y_i)|.
double shoelaceArea(const std::array<Eigen::Vector2d, 4> &p) {
  double twiceArea = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector2d &a = p[i];
    const Eigen::Vector2d &b = p[(i + 1) % p.size()];
    twiceArea += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * std::abs(twiceArea);
}

TEST(CookMembrane, VolumeIsTrapezoidAreaTimesThickness) {
  const double area = shoelaceArea(kCorners);  // mm^2
  ASSERT_DOUBLE_EQ(area, 48.0 * (44.0 + 16.0) / 2.0);
  for (int n : {1, 3, 8}) {
    // Millimetres.
    EXPECT_NEAR(meshVolume(generateCookMembrane(n, 1, 1.0, 1.0)), area * 1.0, 1e-9 * area) << n;
    // Metres: volume scales with scale^3.
    const double scale = 1e-3, thickness = 2.5;
    const double expected = area * thickness * scale * scale * scale;
    EXPECT_NEAR(meshVolume(generateCookMembrane(n, 2, thickness, scale)), expected, 1e-9 * expected)
        << n;
  }
}

TEST(CookMembrane, CountsAndPositiveJacobians) {
  const int n = 6, nz = 2;
  const HexMesh mesh = generateCookMembrane(n, nz, 1.0, 1e-3);
  EXPECT_EQ(mesh.numNodes(), static_cast<std::size_t>((n + 1) * (n + 1) * (nz + 1)));
  EXPECT_EQ(mesh.numElements(), static_cast<std::size_t>(n * n * nz));
  EXPECT_EQ(mesh.elementSets.at("all").size(), mesh.numElements());
  const auto [lo, hi] = scaledJacobianRange(mesh);
  EXPECT_GT(lo, 0.0);
  EXPECT_LE(hi, 1.0 + 1e-12);
}

TEST(CookMembrane, SetSizes) {
  const int n = 5, nz = 3;
  const HexMesh mesh = generateCookMembrane(n, nz, 2.0, 1.0);
  const auto side = static_cast<std::size_t>(n * nz);
  const auto sideNodes = static_cast<std::size_t>((n + 1) * (nz + 1));
  for (const char *name : {"clamped", "loaded", "bottom", "top"}) {
    EXPECT_EQ(mesh.faceSet(name).size(), side) << name;
    EXPECT_EQ(mesh.nodeSet(name).size(), sideNodes) << name;
  }
  for (const char *name : {"front", "back"}) {
    EXPECT_EQ(mesh.faceSet(name).size(), static_cast<std::size_t>(n * n)) << name;
    EXPECT_EQ(mesh.nodeSet(name).size(), static_cast<std::size_t>((n + 1) * (n + 1))) << name;
  }
}

TEST(CookMembrane, SidesLieOnTheirEdgesWithOutwardNormals) {
  const double scale = 1e-3, thickness = 1.5;
  const HexMesh mesh = generateCookMembrane(4, 2, thickness, scale);
  const double tol = 1e-12;
  // Each side as (signed distance to its line/plane in mm, outward direction in x-y-z).
  auto mm = [&](NodeId n) -> Eigen::Vector3d { return mesh.nodes[n] / scale; };
  const Eigen::Vector3d lowerOutward = Eigen::Vector3d(44, -48, 0).normalized();
  const Eigen::Vector3d upperOutward = Eigen::Vector3d(-16, 48, 0).normalized();
  for (NodeId n : mesh.nodeSet("clamped")) EXPECT_NEAR(mm(n).x(), 0.0, tol);
  for (NodeId n : mesh.nodeSet("loaded")) EXPECT_NEAR(mm(n).x(), 48.0, tol);
  for (NodeId n : mesh.nodeSet("bottom")) EXPECT_NEAR(mm(n).y(), 44.0 / 48.0 * mm(n).x(), tol);
  for (NodeId n : mesh.nodeSet("top")) EXPECT_NEAR(mm(n).y(), 44.0 + 16.0 / 48.0 * mm(n).x(), tol);
  for (NodeId n : mesh.nodeSet("front")) EXPECT_NEAR(mm(n).z(), 0.0, tol);
  for (NodeId n : mesh.nodeSet("back")) EXPECT_NEAR(mm(n).z(), thickness, tol);

  const std::array<Eigen::Vector3d, 6> outward = {
      -Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitX(), lowerOutward, upperOutward,
      -Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ()};
  for (std::size_t s = 0; s < kSides.size(); ++s) {
    testing::expectOutwardNormals(mesh, kSides[s]);
    testing::expectNodeSetMatchesFaces(mesh, kSides[s]);
    // Sides are flat, so every face normal is the side's outward unit normal.
    for (const ElementFace &f : mesh.faceSet(kSides[s])) {
      const Hex &hex = mesh.elements[static_cast<std::size_t>(f.element)];
      const auto &local = kHexFaceNodes[static_cast<std::size_t>(f.localFace)];
      const Eigen::Vector3d normal =
          testing::quadAreaVector(mesh.nodes[hex[local[0]]], mesh.nodes[hex[local[1]]],
                                  mesh.nodes[hex[local[2]]], mesh.nodes[hex[local[3]]])
              .normalized();
      EXPECT_NEAR(normal.dot(outward[s]), 1.0, 1e-12) << kSides[s];
    }
  }

  std::vector<ElementFace> sides;
  for (const std::string &name : kSides) {
    sides.insert(sides.end(), mesh.faceSet(name).begin(), mesh.faceSet(name).end());
  }
  std::sort(sides.begin(), sides.end());
  EXPECT_EQ(sides, boundaryFaces(mesh));
}

TEST(CookMembrane, TipIsTheUpperLoadedCornerOnTheFront) {
  const double scale = 1e-3;
  const HexMesh mesh = generateCookMembrane(7, 3, 1.0, scale);
  ASSERT_EQ(mesh.namedPoints.size(), std::size_t{1});
  const NamedPoint &tip = mesh.namedPoints.at("tip");
  const Eigen::Vector3d expected = Eigen::Vector3d(48, 60, 0) * scale;
  EXPECT_LT((tip.position - expected).norm(), 1e-15);
  EXPECT_EQ(mesh.nodes[static_cast<std::size_t>(tip.node)], tip.position);
  EXPECT_EQ(mesh.nearestNode(expected), tip.node);
  for (const char *name : {"loaded", "top", "front"}) {
    const auto &set = mesh.nodeSet(name);
    EXPECT_TRUE(std::binary_search(set.begin(), set.end(), tip.node)) << name;
  }
}

TEST(CookMembrane, RejectsBadInputNamingTheParameter) {
  auto messageOf = [](int cellsXY, int cellsZ, double thickness, double scale) -> std::string {
    try {
      generateCookMembrane(cellsXY, cellsZ, thickness, scale);
    } catch (const std::invalid_argument &e) {
      return e.what();
    }
    return "no exception";
  };
  EXPECT_NE(messageOf(0, 1, 1.0, 1.0).find("cellsXY"), std::string::npos);
  EXPECT_NE(messageOf(2, 0, 1.0, 1.0).find("cellsZ"), std::string::npos);
  EXPECT_NE(messageOf(2, 1, 0.0, 1.0).find("thickness"), std::string::npos);
  EXPECT_NE(messageOf(2, 1, 1.0, -1e-3).find("scale"), std::string::npos);
  EXPECT_NE(messageOf(2, 1, 1.0, NAN).find("scale"), std::string::npos);
}

}  // namespace
}  // namespace glossa::mesh
