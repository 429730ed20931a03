#include "mesh/Partition.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace glossa::mesh {

namespace {

struct Bisection {
  const std::vector<Eigen::Vector3d> &centroid;
  std::vector<int> &owner;

  // Assigns elements [first, last) to parts [firstPart, firstPart + numParts).
  void split(std::vector<ElementId>::iterator first, std::vector<ElementId>::iterator last,
             int firstPart, int numParts) const {
    if (numParts == 1) {
      for (auto it = first; it != last; ++it) owner[static_cast<std::size_t>(*it)] = firstPart;
      return;
    }
    const auto n = static_cast<long long>(last - first);

    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d hi = -lo;
    for (auto it = first; it != last; ++it) {
      lo = lo.cwiseMin(centroid[static_cast<std::size_t>(*it)]);
      hi = hi.cwiseMax(centroid[static_cast<std::size_t>(*it)]);
    }
    // Longest extent; extents equal up to rounding (a cube away from the origin) count as a
    // tie, which goes to the lowest axis, so the split does not hinge on the last bit.
    int axis = 0;
    if (n > 0) {
      const Eigen::Vector3d extent = hi - lo;
      const double longest = extent.maxCoeff();
      while (extent[axis] < (1.0 - 1e-12) * longest) ++axis;
    }

    // Part sizes are q + 1 for the first r parts and q for the rest (q = n / c, r = n % c);
    // the left half takes the first leftParts of them, so both halves stay within [q, q + 1]
    // per part and the sizes of all final parts differ by at most one.
    const int leftParts = numParts / 2;
    const long long q = n / numParts, r = n % numParts;
    const long long leftSize = leftParts * q + std::min<long long>(r, leftParts);

    const auto middle = first + leftSize;
    std::nth_element(first, middle, last, [&](ElementId a, ElementId b) {
      const double xa = centroid[static_cast<std::size_t>(a)][axis];
      const double xb = centroid[static_cast<std::size_t>(b)][axis];
      return xa < xb || (xa == xb && a < b);  // a strict total order: deterministic split
    });
    split(first, middle, firstPart, leftParts);
    split(middle, last, firstPart + leftParts, numParts - leftParts);
  }
};

}  // namespace

std::vector<int> partitionElements(const HexMesh &mesh, int parts) {
  if (parts < 1) {
    throw std::invalid_argument("partitionElements: parts must be >= 1, got " +
                                std::to_string(parts));
  }
  const std::size_t ne = mesh.numElements();
  std::vector<Eigen::Vector3d> centroid(ne);
  std::vector<ElementId> ids(ne);
  for (std::size_t e = 0; e < ne; ++e) {
    centroid[e] = mesh.elementCoordinates(static_cast<ElementId>(e)).colwise().mean().transpose();
    ids[e] = static_cast<ElementId>(e);
  }
  std::vector<int> owner(ne, 0);
  Bisection{centroid, owner}.split(ids.begin(), ids.end(), 0, parts);
  return owner;
}

}  // namespace glossa::mesh
