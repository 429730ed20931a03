#pragma once
// The airway's centreline and its cross-section planes, fixed from the geometry at rest. In the
// midsagittal plane, the tongue's airway surface and the wall each cut a curve; the centreline
// runs along the tongue's curve from the point nearest `start` (e.g. under the velum) to the
// point nearest `end` (e.g. at the vallecula), sampled at the middles of `sections` equal arc
// lengths, each sample t_i paired with the nearest point w_i of the wall's curve, and the
// centreline's point there is the midpoint c_i = (t_i + w_i)/2. Section i is the plane through
// c_i normal to the centreline (the direction c_{i+1} - c_{i-1}, one-sided at the ends, with its
// component along the midsagittal plane's normal removed, so every section is square to that
// plane), its depth axis pointing from t_i to w_i and its lateral axis along the midsagittal
// plane's normal.

#include <Eigen/Core>
#include <array>
#include <vector>

#include "airway/SectionPlane.hpp"

namespace glossa::airway {

struct TriangleSet {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
};

struct CentrelineSettings {
  Eigen::Vector3d midsagittalPoint = Eigen::Vector3d::Zero();
  Eigen::Vector3d lateralAxis = Eigen::Vector3d::UnitY();  // the midsagittal plane's normal
  Eigen::Vector3d start = Eigen::Vector3d::Zero(), end = Eigen::Vector3d::Zero();
  int sections = 20;
};

struct Centreline {
  std::vector<SectionPlane> planes;
  std::vector<double> arcLength;  // of each section's centre along the centreline from the first [m]
  std::vector<Eigen::Vector3d> tonguePoints, wallPoints;  // t_i and w_i at rest
};

// Throws std::invalid_argument naming what is missing: a surface the midsagittal plane does not
// cut, start and end at the same point of the tongue's curve.
Centreline buildCentreline(const TriangleSet &tongue, const TriangleSet &wall, const CentrelineSettings &settings);

}  // namespace glossa::airway
