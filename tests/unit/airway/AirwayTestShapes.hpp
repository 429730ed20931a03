#pragma once
// Faceted surfaces with known cross-sections for the airway's tests: a patch of a surface
// x(s, t) on a grid of ns x nt cells, each cell two triangles.

#include <Eigen/Core>
#include <cmath>
#include <functional>

#include "airway/Centreline.hpp"

namespace glossa::airway::test {

inline TriangleSet gridSurface(int ns, int nt, const std::function<Eigen::Vector3d(double, double)> &x) {
  TriangleSet set;
  for (int j = 0; j <= nt; ++j)
    for (int i = 0; i <= ns; ++i) set.vertices.push_back(x(static_cast<double>(i) / ns, static_cast<double>(j) / nt));
  auto id = [ns](int i, int j) { return j * (ns + 1) + i; };
  for (int j = 0; j < nt; ++j)
    for (int i = 0; i < ns; ++i) {
      set.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      set.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return set;
}

// A flat strip along `axis` from 0 to `length`, across `lateral` from `left` to `right`, through
// `offset`.
inline TriangleSet strip(const Eigen::Vector3d &offset, const Eigen::Vector3d &axis, const Eigen::Vector3d &lateral,
                         double length, double left, double right, int ns = 8, int nt = 5) {
  return gridSurface(ns, nt, [=](double s, double t) {
    return Eigen::Vector3d(offset + s * length * axis + (left + t * (right - left)) * lateral);
  });
}

// Half of a cylinder of radius r about the x axis, from x = 0 to `length`, faceted by `facets`
// of the whole circle: angles from `from` over half a turn (theta from the y axis toward z).
inline TriangleSet halfCylinder(double r, double length, int facets, double from) {
  return gridSurface(4, facets / 2, [=](double s, double t) {
    const double theta = from + t * M_PI;
    return Eigen::Vector3d(s * length, r * std::cos(theta), r * std::sin(theta));
  });
}

}  // namespace glossa::airway::test
