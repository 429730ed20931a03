#pragma once
// The isochoric point law as the element kernel sees it: a response per quadrature point of the
// element being evaluated. A uniform material ignores the point index; an active muscle reads
// the point's history (its committed contractile stretches) and its element's fibre directions
// through it (model/TissuePointLaw.hpp). Returning false marks the element invalid, as J <= 0
// does, so that the step is cut back instead of continuing with a failed local solve.

#include <Eigen/Core>

#include "materials/IsochoricMaterial.hpp"

namespace glossa::fem {

class QuadraturePointLaw {
public:
  virtual ~QuadraturePointLaw() = default;
  // The response at quadrature point q (0..7, the order of gaussHex2()) with deformation
  // gradient F (det F > 0). False if the point law cannot be evaluated there.
  virtual bool evaluate(int q, const Eigen::Matrix3d &F, materials::PointResponse &out) const = 0;
};

// The same history-free material at every point.
class UniformPointLaw final : public QuadraturePointLaw {
public:
  explicit UniformPointLaw(const materials::IsochoricMaterial &material) : material_(material) {}
  bool evaluate(int, const Eigen::Matrix3d &F, materials::PointResponse &out) const override {
    out = material_.evaluate(F);
    return true;
  }

private:
  const materials::IsochoricMaterial &material_;
};

} // namespace glossa::fem
