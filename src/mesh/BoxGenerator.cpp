#include "mesh/BoxGenerator.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "mesh/StructuredHexGrid.hpp"

namespace glossa::mesh {

HexMesh generateBox(const Eigen::Vector3d &origin, const Eigen::Vector3d &lengths,
                    const std::array<int, 3> &cells) {
  for (int d = 0; d < 3; ++d) {
    if (cells[d] < 1) {
      std::ostringstream msg;
      msg << "generateBox: cells[" << d << "] must be >= 1, got " << cells[d];
      throw std::invalid_argument(msg.str());
    }
    if (!(lengths[d] > 0.0) || !std::isfinite(lengths[d])) {
      std::ostringstream msg;
      msg << "generateBox: lengths[" << d << "] must be a positive finite length, got "
          << lengths[d];
      throw std::invalid_argument(msg.str());
    }
    if (!std::isfinite(origin[d])) {
      std::ostringstream msg;
      msg << "generateBox: origin[" << d << "] must be finite, got " << origin[d];
      throw std::invalid_argument(msg.str());
    }
  }

  // x = origin + lengths * (i / n): the far faces land exactly on origin + lengths, so
  // coordinate comparisons against the deck's box need no tolerance there.
  auto position = [&](int i, int j, int k) {
    const Eigen::Vector3d fraction(static_cast<double>(i) / cells[0],
                                   static_cast<double>(j) / cells[1],
                                   static_cast<double>(k) / cells[2]);
    return Eigen::Vector3d(origin + lengths.cwiseProduct(fraction));
  };
  HexMesh mesh =
      structuredHexGrid(cells, position, {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"});
  mesh.namedPoints["origin"] = NamedPoint{mesh.nodes.front(), 0, {}};
  return mesh;
}

}  // namespace glossa::mesh
