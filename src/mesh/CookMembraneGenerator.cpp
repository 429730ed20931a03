#include "mesh/CookMembraneGenerator.hpp"

#include <Eigen/Core>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "mesh/StructuredHexGrid.hpp"

namespace glossa::mesh {

namespace {

void requireAtLeastOne(const char *name, int value) {
  if (value < 1) {
    std::ostringstream msg;
    msg << "generateCookMembrane: " << name << " must be >= 1, got " << value;
    throw std::invalid_argument(msg.str());
  }
}

void requirePositive(const char *name, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    std::ostringstream msg;
    msg << "generateCookMembrane: " << name << " must be a positive finite number, got " << value;
    throw std::invalid_argument(msg.str());
  }
}

}  // namespace

HexMesh generateCookMembrane(int cellsXY, int cellsZ, double thickness, double scale) {
  requireAtLeastOne("cellsXY", cellsXY);
  requireAtLeastOne("cellsZ", cellsZ);
  requirePositive("thickness", thickness);
  requirePositive("scale", scale);

  // Corners of the membrane [mm]: P00 at (s,t) = (0,0), P10 at (1,0), P11 at (1,1), P01 at (0,1).
  const Eigen::Vector2d P00(0.0, 0.0), P10(48.0, 44.0), P11(48.0, 60.0), P01(0.0, 44.0);

  // Bilinear map x(s,t) = (1-s)(1-t) P00 + s(1-t) P10 + s t P11 + (1-s) t P01. Its grid lines
  // are straight, so the elements tile the trapezoid exactly, and at the corners all weights
  // but one are exactly 0, so the tip lands exactly on (48, 60) * scale.
  auto position = [&](int i, int j, int k) {
    const double s = static_cast<double>(i) / cellsXY;
    const double t = static_cast<double>(j) / cellsXY;
    const Eigen::Vector2d xy =
        (1 - s) * (1 - t) * P00 + s * (1 - t) * P10 + s * t * P11 + (1 - s) * t * P01;
    const double z = thickness * (static_cast<double>(k) / cellsZ);
    return Eigen::Vector3d(scale * xy.x(), scale * xy.y(), scale * z);
  };
  HexMesh mesh = structuredHexGrid({cellsXY, cellsXY, cellsZ}, position,
                                   {"clamped", "loaded", "bottom", "top", "front", "back"});

  const NodeId tip = cellsXY + static_cast<NodeId>(cellsXY + 1) * cellsXY;  // (i,j,k)=(n,n,0)
  mesh.namedPoints["tip"] = NamedPoint{mesh.nodes[static_cast<std::size_t>(tip)], tip, {}};
  return mesh;
}

}  // namespace glossa::mesh
