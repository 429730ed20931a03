#include "solvers/stepping/EnergyConservingForces.hpp"

#include <stdexcept>

#include "fem/DiscreteGradient.hpp"

namespace glossa::solvers {

EnergyConservingForces::EnergyConservingForces(std::vector<char> corrected, double weight)
    : corrected_(std::move(corrected)), weight_(weight), committed_(corrected_.size()) {}

void EnergyConservingForces::record(std::size_t i, const fem::NodeMatrix &ue, double lambda, const fem::Q1P0Result &r,
                                    const materials::VolumetricEnergy &volumetric) {
  if (!r.valid) throw std::runtime_error("an inverted element in a converged state");
  Committed &c = committed_.at(i);
  c.u = ue;
  c.volumeGradient = r.volumeGradient;
  c.isochoricForce = r.residual - r.pressure * r.volumeGradient;
  c.referenceVolume = r.referenceVolume;
  c.theta = r.theta;
  c.tangentPressure = r.pressure - lambda;
  c.lambda = lambda;
  c.isochoricEnergy = r.energy - r.referenceVolume * (volumetric.energy(r.theta) + lambda * (r.theta - 1.0));
}

void EnergyConservingForces::add(std::size_t i, const fem::NodeMatrix &ue, double lambda,
                                 const materials::VolumetricEnergy &volumetric, const fem::Q1P0Result &r,
                                 fem::ElementVector &re, fem::ElementMatrix *ke) const {
  if (!corrected_[i]) return;
  const Committed &c = committed_[i];
  // Both ends in the potential W(.; Lambda_mid), u_n's with the law of this evaluation.
  const double lambdaMid = 0.5 * (c.lambda + lambda), dU0 = volumetric.dU(c.theta);
  const fem::ElementVector f0 = c.isochoricForce + (dU0 + lambdaMid) * c.volumeGradient;
  const double W0 = c.isochoricEnergy + c.referenceVolume * (volumetric.energy(c.theta) + lambdaMid * (c.theta - 1.0));
  const fem::ElementVector f1 = r.residual - (lambda - lambdaMid) * r.volumeGradient;
  const double W1 = r.energy - r.referenceVolume * (lambda - lambdaMid) * (r.theta - 1.0);
  const fem::DiscreteGradientCorrection correction =
      fem::discreteGradientCorrection(fem::flattenNodes(ue - c.u), W0, W1, 0.5 * (f0 + f1));
  // The residual holds f(u_{n+1}; Lambda) and the step's committed part f(u_n; Lambda_n) with the
  // law at commit: what the step's force (f0 + f1)/2 + c d differs from their mean goes in.
  const fem::ElementVector committedForce = c.isochoricForce + (c.tangentPressure + c.lambda) * c.volumeGradient;
  re += weight_ * (0.5 * (f0 - committedForce) + 0.5 * (f1 - r.residual) + correction.force);
  // A negative c would make the tangent indefinite where the linear solver assumes it is not
  // (conjugate gradients): the tangent, only Newton's guide, then leaves it out.
  if (ke && correction.coefficient > 0.0) fem::addTranslationFreeIdentity(*ke, weight_ * correction.coefficient);
}

} // namespace glossa::solvers
