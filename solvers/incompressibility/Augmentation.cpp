#include "solvers/incompressibility/Augmentation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "io/deck/DeckError.hpp"

namespace glossa::solvers {

double Augmentation::augmentationKappa(const IncompressibilityParameters &p, double mu) { return p.penaltyRatio * mu; }

double Augmentation::tangentKappa(const IncompressibilityParameters &s, double materialKappa, double mu) {
  // Mixed: the kernel carries no volumetric energy; the pressure unknowns carry the law.
  if (s.method == IncompressibilityMethod::mixed) return 0.0;
  if (s.method == IncompressibilityMethod::augmentedLagrangian)
    return AugmentedLagrangianRule(materials::VolumetricEnergy(materials::VolumetricEnergy::Form::Quadratic, materialKappa),
                                   augmentationKappa(s, mu))
        .tangentKappa();
  if (!std::isfinite(materialKappa))
    throw io::DeckError("Material: an infinite bulk modulus (Poisson's ratio = 0.5, exact incompressibility) "
                        "needs Incompressibility/method = augmented Lagrangian or mixed; a penalty needs nu < 0.5");
  return materialKappa;
}

Augmentation::Augmentation(const IncompressibilityParameters &parameters,
                           std::vector<materials::VolumetricEnergy> physical, std::vector<double> mu)
    : parameters_(parameters), physical_(std::move(physical)), mu_(std::move(mu)) {
  if (mu_.size() != physical_.size())
    throw std::invalid_argument("Augmentation: " + std::to_string(mu_.size()) + " shear moduli for " +
                                std::to_string(physical_.size()) + " tissues");
  for (std::size_t t = 0; t < physical_.size(); ++t) {
    tangent_.push_back(physical_[t].withKappa(tangentKappa(parameters_, physical_[t].kappa(), mu_[t])));
    ratio_.push_back(parameters_.penaltyRatio);
    rules_.emplace_back(physical_[t], ratio_[t] * mu_[t]);
  }
}

void Augmentation::setRatio(std::size_t tissue, double ratio) {
  if (tissue >= ratio_.size())
    throw std::out_of_range("Augmentation::setRatio: no tissue " + std::to_string(tissue));
  ratio_[tissue] = ratio;
  rules_[tissue] = AugmentedLagrangianRule(physical_[tissue], ratio * mu_[tissue]);
  if (parameters_.method == IncompressibilityMethod::augmentedLagrangian)
    tangent_[tissue] = physical_[tissue].withKappa(rules_[tissue].tangentKappa());
}

materials::VolumetricEnergy Augmentation::constrainedLaw(std::size_t tissue, double ratio) const {
  const materials::VolumetricEnergy &law = physical_.at(tissue);
  return law.withKappa(std::min(law.kappa(), ratio * mu_[tissue]));
}

std::vector<materials::VolumetricEnergy> Augmentation::exchangeTangentLaws(std::vector<materials::VolumetricEnergy> laws) {
  if (laws.size() != tangent_.size())
    throw std::invalid_argument("Augmentation::exchangeTangentLaws: " + std::to_string(laws.size()) + " laws for " +
                                std::to_string(tangent_.size()) + " tissues");
  std::vector<materials::VolumetricEnergy> held(tangent_);
  std::copy(laws.begin(), laws.end(), tangent_.begin());
  return held;
}

} // namespace glossa::solvers
