#include "assembly/MixedPressureState.hpp"

#include <cmath>

namespace glossa::assembly {

void MixedPressureState::initialise(const Assembler &assembler) {
  const Vector zero(assembler.layout().ownedMap());
  const PressureCoupling reference = assembler.pressureCoupling(zero);
  pressureScale = Teuchos::rcp(new Vector(reference.pressureMap));
  auto scale = pressureScale->getDataNonConst(0);
  sigma.resize(reference.referenceVolume.size());
  constraintTerms = 0.0;
  for (std::size_t i = 0; i < sigma.size(); ++i) {
    const double V = reference.referenceVolume[i];
    sigma[i] = scale[i] = shearModulus / std::cbrt(V);
    constraintTerms += (sigma[i] * V) * (sigma[i] * V);
  }
}

void MixedPressureState::linearise(const Assembler &assembler, const Vector &u, const std::vector<double> &pressure) {
  coupling = assembler.pressureCoupling(u);
  const auto map = coupling.pressureMap;
  compliance = Teuchos::rcp(new Vector(map));
  schurDiagonal = Teuchos::rcp(new Vector(map));
  constraintResidual = Teuchos::rcp(new Vector(map));
  auto c = compliance->getDataNonConst(0);
  auto s = schurDiagonal->getDataNonConst(0);
  auto r = constraintResidual->getDataNonConst(0);
  const bool incompressible = !std::isfinite(physical.kappa());
  for (std::size_t i = 0; i < pressure.size(); ++i) {
    const double V = coupling.referenceVolume[i];
    const double theta = physical.dilatationAtPressure(pressure[i]);
    // d theta_phys / dp = 1 / U''(theta_phys): the element's volume compliance.
    c[i] = incompressible ? 0.0 : sigma[i] * sigma[i] * V / physical.d2U(theta);
    s[i] = c[i] + sigma[i] * sigma[i] * V / shearModulus;
    r[i] = sigma[i] * (coupling.currentVolume[i] - V * theta);
  }
  coupling.volumeGradient->leftScale(*pressureScale);
}

} // namespace glossa::assembly
