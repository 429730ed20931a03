#include "mesh/ThickCylinderGenerator.hpp"

#include <cmath>
#include <stdexcept>

#include "mesh/StructuredHexGrid.hpp"

namespace glossa::mesh {

HexMesh generateThickCylinder(double innerRadius, double outerRadius, double height, const std::array<int, 3> &cells) {
  if (!(innerRadius > 0.0) || !(outerRadius > innerRadius) || !std::isfinite(outerRadius))
    throw std::invalid_argument("generateThickCylinder: need 0 < inner radius < outer radius");
  if (!(height > 0.0) || !std::isfinite(height))
    throw std::invalid_argument("generateThickCylinder: height must be a positive finite number");
  // (i, j, k) -> (r, phi, z): e_r x e_phi = e_z, orientation-preserving.
  HexMesh m = structuredHexGrid(
      cells,
      [&](int i, int j, int k) {
        const double r = innerRadius + (outerRadius - innerRadius) * i / cells[0];
        const double phi = 0.5 * M_PI * j / cells[1];
        // Exact 0 on the symmetry planes, so that node sets select them cleanly.
        const double c = j == cells[1] ? 0.0 : std::cos(phi), s = j == 0 ? 0.0 : std::sin(phi);
        return Eigen::Vector3d(r * c, r * s, height * k / cells[2]);
      },
      {"inner", "outer", "y0", "x0", "zmin", "zmax"});
  m.namedPoints["inner"] = {m.nodes[0], 0, {}};
  return m;
}

} // namespace glossa::mesh
