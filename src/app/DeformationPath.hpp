#pragma once
// glossa point's deformation path in time: the deformation gradient F(t) of the deck's Point
// section (input/PointParameters.hpp gives the paths' formulas) and the path's parameter.

#include <Eigen/Core>

#include "input/PointParameters.hpp"

namespace glossa::app {

// lambda - 1 (uniaxial) or gamma (simple shear): amplitude s(t); 0 for a table, which has none.
double pathParameter(const input::PointParameters &point, double t);

// F(t). A table is linear in time between its rows and constant before the first and after the
// last.
Eigen::Matrix3d deformationGradient(const input::PointParameters &point, double t);

} // namespace glossa::app
