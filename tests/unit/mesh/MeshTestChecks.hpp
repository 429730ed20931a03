#pragma once
// Checks several mesh tests share. They recompute geometry from raw node coordinates rather
// than through the library's helpers, so that a bug there cannot hide itself.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "mesh/HexMesh.hpp"
#include "mesh/MeshChecks.hpp"
#include "mesh/MeshQuality.hpp"

namespace glossa::mesh::testing {

// Area-weighted normal of a (possibly warped) quadrilateral a-b-c-d: half the cross product of
// its diagonals, (c - a) x (d - b) / 2, pointing by the right-hand rule of the node order.
inline Eigen::Vector3d quadAreaVector(const Eigen::Vector3d &a, const Eigen::Vector3d &b,
                                      const Eigen::Vector3d &c, const Eigen::Vector3d &d) {
  return 0.5 * (c - a).cross(d - b);
}

// Every face of the set has a right-hand normal pointing away from its element's centroid.
inline void expectOutwardNormals(const HexMesh &mesh, const std::string &faceSetName) {
  const auto &faces = mesh.faceSet(faceSetName);
  ASSERT_FALSE(faces.empty()) << faceSetName;
  for (const ElementFace &f : faces) {
    const Hex &hex = mesh.elements[static_cast<std::size_t>(f.element)];
    Eigen::Vector3d elementCentre = Eigen::Vector3d::Zero();
    for (NodeId n : hex) elementCentre += mesh.nodes[static_cast<std::size_t>(n)] / 8.0;
    const auto &local = kHexFaceNodes[static_cast<std::size_t>(f.localFace)];
    std::array<Eigen::Vector3d, 4> x;
    Eigen::Vector3d faceCentre = Eigen::Vector3d::Zero();
    for (int a = 0; a < 4; ++a) {
      x[a] = mesh.nodes[static_cast<std::size_t>(hex[local[a]])];
      faceCentre += x[a] / 4.0;
    }
    const Eigen::Vector3d normal = quadAreaVector(x[0], x[1], x[2], x[3]);
    EXPECT_GT(normal.dot(faceCentre - elementCentre), 0.0)
        << faceSetName << ": element " << f.element << " face " << f.localFace;
  }
}

// The node set of a face set is exactly the nodes its faces touch.
inline void expectNodeSetMatchesFaces(const HexMesh &mesh, const std::string &name) {
  std::vector<NodeId> touched;
  for (const ElementFace &f : mesh.faceSet(name)) {
    for (int a : kHexFaceNodes[static_cast<std::size_t>(f.localFace)]) {
      touched.push_back(mesh.elements[static_cast<std::size_t>(f.element)][a]);
    }
  }
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  EXPECT_EQ(mesh.nodeSet(name), touched) << name;
}

// A generator's mesh passes every check before a run (its blocks' shared nodes merged), is one
// part, and no corner's scaled Jacobian is below `minScaledJacobian`.
inline void expectValidConformingMesh(const HexMesh &mesh, double minScaledJacobian) {
  const MeshCheckReport report = checkMesh(mesh);
  EXPECT_TRUE(report.unusedNodes.empty());
  EXPECT_TRUE(report.coincidentNodes.empty());
  EXPECT_TRUE(report.duplicateElements.empty());
  EXPECT_TRUE(report.invertedCorners.empty());
  EXPECT_EQ(meshParts(mesh).second, 1);
  EXPECT_GT(scaledJacobianRange(mesh).first, minScaledJacobian);
}

}  // namespace glossa::mesh::testing
