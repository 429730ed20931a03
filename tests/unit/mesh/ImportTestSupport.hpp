#pragma once
// Helpers for the mesh-import tests: scratch files and error-message checks, plus geometry
// recomputed from raw coordinates (not through the library) so that the readers are checked
// against an independent computation.

#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "ScratchDir.hpp"
#include "mesh/HexMesh.hpp"

namespace glossa::mesh::testing {

using ScratchDir = glossa::test::ScratchDir; // a fresh directory per test (tests/unit/ScratchDir.hpp)

// Runs f, expects std::runtime_error whose message contains every fragment.
inline void expectError(const std::function<void()> &f, const std::vector<std::string> &fragments) {
  try {
    f();
    ADD_FAILURE() << "no error; expected one containing '" << fragments.front() << "'";
  } catch (const std::runtime_error &e) {
    const std::string message = e.what();
    for (const std::string &fragment : fragments) {
      EXPECT_NE(message.find(fragment), std::string::npos) << "'" << fragment << "' not in: " << message;
    }
  }
}

// Faces (as local-face node lists of their element) that occur in exactly one element.
inline std::vector<std::array<NodeId, 4>> boundaryQuads(const HexMesh &mesh) {
  // Independent of HexMesh::boundaryFaces: faces written out from the VTK hex directly.
  static const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                  {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  std::map<std::array<NodeId, 4>, std::vector<std::array<NodeId, 4>>> byKey;
  for (const Hex &hex : mesh.elements) {
    for (const auto &f : faces) {
      std::array<NodeId, 4> quad{hex[f[0]], hex[f[1]], hex[f[2]], hex[f[3]]};
      std::array<NodeId, 4> key = quad;
      std::sort(key.begin(), key.end());
      byKey[key].push_back(quad);
    }
  }
  std::vector<std::array<NodeId, 4>> result;
  for (const auto &[key, quads] : byKey) {
    if (quads.size() == 1) result.push_back(quads.front());
  }
  return result;
}

// Volume enclosed by the boundary by the divergence theorem, V = 1/3 \oint x . n dA, with each
// bilinear face integrated by 2x2 Gauss (x . (x_s x x_t) is biquadratic: exact).
inline double volumeByDivergence(const HexMesh &mesh) {
  const double g = 1.0 / std::sqrt(3.0);
  double V = 0.0;
  for (const auto &q : boundaryQuads(mesh)) {
    std::array<Eigen::Vector3d, 4> x;
    for (int a = 0; a < 4; ++a) x[a] = mesh.nodes[static_cast<std::size_t>(q[a])];
    for (double s : {-g, g}) {
      for (double t : {-g, g}) {
        // x(s,t) = sum N_a x_a on [-1,1]^2 with nodes at (-1,-1), (1,-1), (1,1), (-1,1).
        const double ss[4] = {-1, 1, 1, -1}, tt[4] = {-1, -1, 1, 1};
        Eigen::Vector3d p = Eigen::Vector3d::Zero(), ps = p, pt = p;
        for (int a = 0; a < 4; ++a) {
          p += 0.25 * (1 + ss[a] * s) * (1 + tt[a] * t) * x[a];
          ps += 0.25 * ss[a] * (1 + tt[a] * t) * x[a];
          pt += 0.25 * tt[a] * (1 + ss[a] * s) * x[a];
        }
        V += p.dot(ps.cross(pt)) / 3.0;
      }
    }
  }
  return V;
}

// A Gmsh script of a 2 x 1 x 3 box: 4 x 2 transfinite quads on z = 0 extruded in 4 layers, so 32
// hexahedra and 5 x 3 x 5 = 75 nodes; physical groups for the volume, the bottom and the top, and
// with `cornerGroup` a physical point at the origin.
inline std::string gmshBoxGeo(bool cornerGroup) {
  std::string geo = R"(SetFactory("Built-in");
Point(1) = {0,0,0}; Point(2) = {2,0,0}; Point(3) = {2,1,0}; Point(4) = {0,1,0};
Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4}; Line(4) = {4,1};
Curve Loop(1) = {1,2,3,4}; Plane Surface(1) = {1};
Transfinite Curve{1,3} = 5; Transfinite Curve{2,4} = 3; Transfinite Surface{1}; Recombine Surface{1};
out[] = Extrude {0,0,3} { Surface{1}; Layers{4}; Recombine; };
Physical Volume("body") = {out[1]};
Physical Surface("bottom") = {1};
Physical Surface("top") = {out[0]};
)";
  if (cornerGroup) geo += "Physical Point(\"corner\") = {1};\n";
  return geo;
}

}  // namespace glossa::mesh::testing
