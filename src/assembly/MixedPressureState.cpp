#include "assembly/MixedPressureState.hpp"

#include <cmath>

namespace glossa::assembly {

void MixedPressureState::linearise(const Assembler &assembler, const Vector &u, const std::vector<double> &pressure) {
  coupling = assembler.pressureCoupling(u);
  const auto map = coupling.pressureMap;
  pressureScale = Teuchos::rcp(new Vector(map));
  compliance = Teuchos::rcp(new Vector(map));
  schurDiagonal = Teuchos::rcp(new Vector(map));
  constraintResidual = Teuchos::rcp(new Vector(map));
  auto sigma = pressureScale->getDataNonConst(0);
  auto c = compliance->getDataNonConst(0);
  auto s = schurDiagonal->getDataNonConst(0);
  auto r = constraintResidual->getDataNonConst(0);
  const bool incompressible = !std::isfinite(physical.kappa());
  for (std::size_t i = 0; i < pressure.size(); ++i) {
    const double V = coupling.referenceVolume[i];
    const double theta = physical.dilatationAtPressure(pressure[i]);
    // d theta_phys / dp = 1 / U''(theta_phys): the element's volume compliance.
    sigma[i] = shearModulus / std::cbrt(V);
    c[i] = incompressible ? 0.0 : sigma[i] * sigma[i] * V / physical.d2U(theta);
    s[i] = c[i] + sigma[i] * sigma[i] * V / shearModulus;
    r[i] = sigma[i] * (coupling.currentVolume[i] - V * theta);
  }
  sigma = Teuchos::null;
  coupling.volumeGradient->leftScale(*pressureScale);
}

std::vector<double> MixedPressureState::pressureScales(const Assembler &assembler) const {
  const Vector zero(assembler.ownedMap());
  const PressureCoupling reference = assembler.pressureCoupling(zero);
  std::vector<double> sigma(reference.referenceVolume.size());
  for (std::size_t i = 0; i < sigma.size(); ++i) sigma[i] = shearModulus / std::cbrt(reference.referenceVolume[i]);
  return sigma;
}

} // namespace glossa::assembly
