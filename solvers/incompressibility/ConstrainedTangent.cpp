#include "solvers/incompressibility/ConstrainedTangent.hpp"

#include "solvers/incompressibility/Augmentation.hpp"

namespace glossa::solvers {

ConstrainedTangent::ConstrainedTangent(Augmentation &augmentation, const assembly::ResultEvaluator &results,
                                       const assembly::Vector &u, const std::vector<double> &lambda, double ratio)
    : augmentation_(augmentation) {
  // p_e and theta_e with the augmented laws, before they are exchanged.
  const assembly::ElementFields fields = results.elementDilatations(u, lambda);
  std::vector<materials::VolumetricEnergy> constrained;
  for (std::size_t t = 0; t < augmentation.tissues(); ++t) constrained.push_back(augmentation.constrainedLaw(t, ratio));
  const model::Scene &scene = results.scene();
  const auto &elements = results.assembler().layout().localElements;
  multipliers_.resize(elements.size());
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const auto e = static_cast<std::size_t>(elements[i]);
    const std::size_t tissue = scene.elementTissue.empty() ? 0 : static_cast<std::size_t>(scene.elementTissue[e]);
    multipliers_[i] = fields.pressure[i] - constrained[tissue].dU(fields.theta[i]);
  }
  augmented_ = augmentation.exchangeTangentLaws(std::move(constrained));
}

ConstrainedTangent::~ConstrainedTangent() { augmentation_.exchangeTangentLaws(std::move(augmented_)); }

} // namespace glossa::solvers
