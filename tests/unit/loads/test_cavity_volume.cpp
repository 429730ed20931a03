// The volume a cavity's wall encloses (faceVolumeMoment summed over a face set, the
// volumes.csv measure) on the octant of a thick sphere, whose cavity is cut by the three
// symmetry planes through the origin (there x . n = 0, so the wall alone measures the cavity):
// it converges at second order to the octant's pi/6 a^3, stays exact under an affine map
// (det F), and with the rest of the boundary gives the element-integrated mesh volume.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <Eigen/LU>

#include "loads/DeadTraction.hpp"
#include "mesh/MeshQuality.hpp"
#include "mesh/ThickSphereGenerator.hpp"

namespace {

using glossa::mesh::HexMesh;

// sum over the set's faces of 1/3 int x . n da at positions x = map(X) (outward normals of the
// body, so a cavity's wall gives minus the cavity's volume).
template <class Map>
double enclosed(const HexMesh &mesh, const std::string &set, const Map &map) {
  double v = 0.0;
  for (const auto &f : mesh.faceSet(set)) {
    glossa::loads::FaceNodes x;
    const auto &hex = mesh.elements[static_cast<std::size_t>(f.element)];
    for (int a = 0; a < 4; ++a)
      x.row(a) = map(mesh.nodes[static_cast<std::size_t>(hex[glossa::mesh::kHexFaceNodes[f.localFace][a]])]).transpose();
    v += glossa::loads::faceVolumeMoment(x);
  }
  return v;
}

const auto identity = [](const Eigen::Vector3d &X) { return X; };

TEST(CavityVolume, ThickSphereCavityConvergesToItsClosedForm) {
  const double a = 1.0, b = 2.0, exact = M_PI / 6.0 * a * a * a;
  double previous = 0.0, error = 0.0;
  for (int n : {4, 8, 16, 32}) {
    const HexMesh mesh = glossa::mesh::generateThickSphere(a, b, 1, n);
    error = std::abs(-enclosed(mesh, "inner", identity) / exact - 1.0);
    std::printf("n = %d: cavity volume error %.3e\n", n, error);
    if (previous > 0.0) {
      EXPECT_NEAR(previous / error, 4.0, 0.5) << "n = " << n;
    }
    previous = error;
  }
  EXPECT_LT(error, 5e-4); // n = 32
}

TEST(CavityVolume, AffineMapScalesByTheDeterminantAndTheBoundaryIsTheBody) {
  const HexMesh mesh = glossa::mesh::generateThickSphere(1.0, 2.0, 3, 6);
  const double cavity = -enclosed(mesh, "inner", identity);
  Eigen::Matrix3d F;
  F << 1.2, 0.0, 0.0, //
      0.0, 0.9, 0.0,  //
      0.0, 0.0, 1.1; // a stretch along the axes keeps the symmetry planes through the origin
  const auto stretched = [&](const Eigen::Vector3d &X) { return Eigen::Vector3d(F * X); };
  EXPECT_NEAR(-enclosed(mesh, "inner", stretched), F.determinant() * cavity, 1e-13);
  // Inner wall, outer surface and the three planes close the body: its volume, integrated
  // independently over the elements.
  double body = 0.0;
  for (const char *set : {"inner", "outer", "x0", "y0", "z0"}) body += enclosed(mesh, set, identity);
  EXPECT_NEAR(body, glossa::mesh::meshVolume(mesh), 1e-13);
  EXPECT_NEAR(enclosed(mesh, "x0", identity), 0.0, 1e-15); // x . n = 0 on the planes
}

} // namespace
