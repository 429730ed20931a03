#include "mesh/QuarterCylinderGenerator.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace glossa::mesh {

namespace {

// The inner square's half-width over the radius: the O-grid's usual half, which keeps the
// corners of the blocks' cells near right angles.
constexpr double kInner = 0.5;

// Node positions 0..n of a geometric progression over [0, 1] with ratio q per cell.
std::vector<double> progression(int n, double q) {
  std::vector<double> s(static_cast<std::size_t>(n) + 1, 0.0);
  double cell = 1.0;
  for (int i = 1; i <= n; ++i, cell *= q) s[i] = s[i - 1] + cell;
  for (double &v : s) v /= s[n];
  s[n] = 1.0;
  return s;
}

// The ratio q >= 1 for which n cells starting at `first` span `length`; 1 where n equal cells are
// already no longer than `first`.
double ratioForFirstCell(int n, double first, double length) {
  if (first * n >= length) return 1.0;
  double lo = 1.0, hi = 2.0;
  const auto span = [&](double q) { return first * (std::pow(q, n) - 1.0) / (q - 1.0); };
  while (span(hi) < length) hi *= 2.0;
  for (int it = 0; it < 200; ++it) (span(0.5 * (lo + hi)) < length ? lo : hi) = 0.5 * (lo + hi);
  return 0.5 * (lo + hi);
}

// Node positions over [0, 1]: `band` equal cells up to `bandEnd`, then `rest` cells growing
// geometrically from the band's cell size to 1.
std::vector<double> bandThenGeometric(int band, int rest, double bandEnd) {
  const double cell = bandEnd / band;
  std::vector<double> s(static_cast<std::size_t>(band + rest) + 1, 0.0);
  for (int i = 1; i <= band; ++i) s[i] = i == band ? bandEnd : cell * i;
  const std::vector<double> tail = progression(rest, ratioForFirstCell(rest, cell, 1.0 - bandEnd));
  for (int i = 1; i <= rest; ++i) s[band + i] = i == rest ? 1.0 : bandEnd + (1.0 - bandEnd) * tail[i];
  return s;
}

// A node of the cross-section: block 0 the inner square (a along x, b along the depth below the
// axis), 1 the contact block (a the contact angle's index, b the radial one), 2 the side block
// (a the side angle's index); plus its layer.
using Address = std::array<int, 4>;

} // namespace

HexMesh generateQuarterCylinder(double radius, double height, const QuarterCylinderCells &cells, double bandWidth) {
  if (!(radius > 0.0) || !std::isfinite(radius) || !(height > 0.0) || !std::isfinite(height))
    throw std::invalid_argument("generateQuarterCylinder: radius and height must be positive finite numbers");
  if (!(bandWidth > 0.0) || !(bandWidth < radius * std::sqrt(0.5)))
    throw std::invalid_argument("generateQuarterCylinder: fine band " + std::to_string(bandWidth) +
                                " m must lie in (0, radius / sqrt 2 = " + std::to_string(radius * std::sqrt(0.5)) +
                                " m), the x of the arc's 45 degree point");
  if (cells.band < 1 || cells.contact < 1 || cells.side < 1 || cells.radial < 1 || cells.axial < 1)
    throw std::invalid_argument("generateQuarterCylinder: cell counts must be >= 1");
  const int na = cells.band + cells.contact, nb = cells.side, nr = cells.radial, nz = cells.axial;
  const double quarter = 0.25 * M_PI;
  // Contact angles from straight down, over pi/4: equal in the band, then growing; side angles
  // from the top plane, equal.
  const std::vector<double> theta = bandThenGeometric(cells.band, cells.contact, std::asin(bandWidth / radius) / quarter);
  const std::vector<double> psi = progression(nb, 1.0);
  // Along a ray, rho = 0 at the inner square and 1 on the arc; the ray straight down is R/2 long,
  // so the band cell's length R (theta[1] pi/4) is 2 (theta[1] pi/4) in rho.
  const std::vector<double> fromArc = progression(nr, ratioForFirstCell(nr, 2.0 * quarter * theta[1], 1.0));
  const auto rho = [&](int r) { return 1.0 - fromArc[static_cast<std::size_t>(nr - r)]; };

  // Nodes shared by two blocks get the address of one of them, so they merge exactly.
  const auto canonical = [&](int block, int a, int b) -> std::array<int, 3> {
    if (block == 2 && a == nb) std::tie(block, a) = std::pair(1, na); // the 45 degree ray
    if (block == 2 && b == 0) return {0, na, a};                      // the inner square's side x = R/2
    if (block == 1 && b == 0) return {0, a, nb}; // the inner square's side R/2 below the axis
    return {block, a, b};
  };
  // Position in the cross-section as (x, depth below the axis); exact zeros on x = 0 and the top.
  const auto section = [&](const std::array<int, 3> &c) -> std::array<double, 2> {
    const double h = kInner * radius;
    if (c[0] == 0) {
      const double x = c[1] == 0 ? 0.0 : h * std::tan(quarter * theta[c[1]]);
      const double d = c[2] == 0 ? 0.0 : h * std::tan(quarter * psi[c[2]]);
      return {x, d};
    }
    const double w = rho(c[2]);
    if (c[0] == 1) {
      const double t = quarter * theta[c[1]], s = c[1] == 0 ? 0.0 : std::sin(t);
      return {(1.0 - w) * h * std::tan(t) + w * radius * s, (1.0 - w) * h + w * radius * std::cos(t)};
    }
    const double t = quarter * psi[c[1]], s = c[1] == 0 ? 0.0 : std::sin(t);
    return {(1.0 - w) * h + w * radius * std::cos(t), (1.0 - w) * h * std::tan(t) + w * radius * s};
  };

  HexMesh m;
  std::map<Address, NodeId> ids;
  const auto node = [&](int block, int a, int b, int k) {
    const auto c = canonical(block, a, b);
    const auto [it, fresh] = ids.try_emplace(Address{c[0], c[1], c[2], k}, static_cast<NodeId>(m.nodes.size()));
    if (fresh) {
      const auto p = section(c);
      m.nodes.emplace_back(p[0], p[1] == 0.0 ? radius : radius - p[1], k == nz ? height : height * k / nz);
    }
    return it->second;
  };
  const std::array<std::array<int, 2>, 3> extent = {{{na, nb}, {na, nr}, {nb, nr}}};
  for (int block = 0; block < 3; ++block)
    for (int k = 0; k < nz; ++k)
      for (int b = 0; b < extent[block][1]; ++b)
        for (int a = 0; a < extent[block][0]; ++a) {
          Hex hex{};
          const std::array<std::array<int, 2>, 4> corner = {{{a, b}, {a + 1, b}, {a + 1, b + 1}, {a, b + 1}}};
          for (int i = 0; i < 4; ++i) {
            hex[i] = node(block, corner[i][0], corner[i][1], k);
            hex[i + 4] = node(block, corner[i][0], corner[i][1], k + 1);
          }
          // Counter-clockwise seen from +z, so the hexahedron is right-handed.
          const Eigen::Vector3d e1 = m.nodes[hex[2]] - m.nodes[hex[0]], e2 = m.nodes[hex[3]] - m.nodes[hex[1]];
          if (e1.x() * e2.y() - e1.y() * e2.x() < 0.0) {
            std::swap(hex[1], hex[3]);
            std::swap(hex[5], hex[7]);
          }
          m.elements.push_back(hex);
        }
  // Each boundary face by where its corners lie: the planes exactly, the rest on the arc.
  for (const ElementFace &f : boundaryFaces(m)) {
    const auto on = [&](auto test) {
      return std::all_of(kHexFaceNodes[f.localFace].begin(), kHexFaceNodes[f.localFace].end(),
                         [&](int a) { return test(m.nodes[m.elements[f.element][a]]); });
    };
    const char *set = on([&](const Eigen::Vector3d &x) { return x.z() == 0.0; })       ? "zmin"
                      : on([&](const Eigen::Vector3d &x) { return x.z() == height; }) ? "zmax"
                      : on([&](const Eigen::Vector3d &x) { return x.x() == 0.0; })    ? "x0"
                      : on([&](const Eigen::Vector3d &x) { return x.y() == radius; }) ? "top"
                                                                                      : "arc";
    m.faceSets[set].push_back(f);
  }
  for (const auto &[name, faces] : m.faceSets) m.nodeSets[name] = m.nodesOfFaceSet(name);
  auto &all = m.elementSets["all"];
  for (std::size_t e = 0; e < m.numElements(); ++e) all.push_back(static_cast<ElementId>(e));
  const NodeId lowest = ids.at({1, 0, nr, 0}), axis = ids.at({0, 0, 0, 0});
  m.namedPoints["lowest"] = {m.nodes[static_cast<std::size_t>(lowest)], lowest, {}};
  m.namedPoints["axis"] = {m.nodes[static_cast<std::size_t>(axis)], axis, {}};
  return m;
}

} // namespace glossa::mesh
