#pragma once
// A deck's three-component array (a point, a direction, a gravity vector) as the Eigen vector the
// scene keeps; the deck's declarations have already checked that it has three entries.

#include <Eigen/Core>
#include <Teuchos_Array.hpp>

namespace glossa::input {

inline Eigen::Vector3d vec3(const Teuchos::Array<double> &a) { return {a[0], a[1], a[2]}; }

} // namespace glossa::input
