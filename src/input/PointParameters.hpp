#pragma once
// The deck's "Point" section: the deformation path of glossa point's one material point, declared
// and parsed once, with the checks that need more than one of its parameters. Paths:
//   uniaxial      F = lambda e(x)e + lambda^{-1/2} (1 - e(x)e): incompressible stretch along e
//   simple shear  F = 1 + gamma e(x)m, m the shear plane's normal (orthogonal to e)
//   table         F(t) given row by row (9 values, row-major), linear in time between rows
// with lambda = 1 + amplitude s(t), gamma = amplitude s(t), s the section's time function
// (app/DeformationPath.hpp evaluates them).

#include <vector>

#include <Eigen/Core>
#include <Teuchos_ParameterList.hpp>

#include "io/deck/Deck.hpp"
#include "model/TimeFunction.hpp"

namespace glossa::input {

enum class PointPath { uniaxial, simpleShear, table };

struct PointParameters {
  PointPath path = PointPath::uniaxial;
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();        // e, of unit length
  Eigen::Vector3d shearPlaneNormal = Eigen::Vector3d::UnitY(); // m, of unit length for simple shear
  double amplitude = 0.2;                                      // lambda - 1 or gamma where s = 1
  model::TimeFunction scale = model::TimeFunction::constant(); // s(t)
  std::vector<double> times;                                   // table: strictly increasing [s]
  std::vector<Eigen::Matrix3d> table;                          // table: F at each time, det F > 0
  Eigen::Vector3d position = Eigen::Vector3d::Zero(); // where the point sits [m] (fibre fields vary in space)
};

Teuchos::ParameterList pointParameters();

// `deck` validated against a schema holding pointParameters() as "Point"; `endTime`: the run's
// end time, the default ramp's duration. Throws io::DeckError naming the parameter (file, line,
// path) for a zero direction, a shear plane normal that is zero or not orthogonal to it (simple
// shear), and a table whose F has not 9 values per time, whose times do not increase strictly or
// that has a row with det F <= 0.
PointParameters parsePointParameters(const io::Deck &deck, double endTime);

} // namespace glossa::input
