#include "model/MuscleHistory.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace glossa::model {

int MuscleArchitecture::groupIndex(const std::string &name) const {
  for (std::size_t g = 0; g < groups.size(); ++g)
    if (groups[g].name == name) return static_cast<int>(g);
  return -1;
}

MuscleHistory::MuscleHistory(const MuscleArchitecture &architecture, const std::vector<mesh::ElementId> &elements)
    : architecture_(&architecture) {
  std::size_t n = 0;
  for (const auto e : elements) {
    const int r = architecture.hasFibres() ? architecture.elementRegion.at(static_cast<std::size_t>(e)) : -1;
    region_.push_back(r);
    offset_.push_back(n);
    if (r >= 0) n += 8 * static_cast<std::size_t>(architecture.regions[r].law->familyCount());
  }
  // The zero-strain configuration is the optimal length: lambda_c = 1 (MuscleMaterial::initialLambdaC).
  lambdaC_.assign(n, 1.0);
  lambdaCTrial_ = lambdaC_;
  resetLambdaCStarts();
  for (const auto &m : architecture.external) externalLambdaC_.emplace_back(m.fibres.size(), 1.0);
  externalLambdaCTrial_ = externalLambdaC_;
  for (const auto &g : architecture.groups) alpha_.push_back(g.initialActivation);
  alphaTrial_ = alpha_;
  inputTrial_.assign(alpha_.size(), 0.0);
}

double MuscleHistory::input(int group, double t) const {
  return std::clamp(architecture_->groups[group].input(t), 0.0, 1.0);
}

void MuscleHistory::beginStep(double tNew, double dt, const std::vector<double> &inputs) {
  if (!(dt > 0.0)) throw std::invalid_argument("MuscleHistory::beginStep: dt must be positive");
  if (!inputs.empty() && inputs.size() != alpha_.size())
    throw std::invalid_argument("MuscleHistory::beginStep: " + std::to_string(inputs.size()) + " inputs for " +
                                std::to_string(alpha_.size()) + " muscle groups");
  dt_ = dt;
  timeTrial_ = tNew;
  ++revision_;
  if (!architecture_) return;
  for (std::size_t g = 0; g < alpha_.size(); ++g) {
    inputTrial_[g] = inputs.empty() ? input(static_cast<int>(g), tNew) : std::clamp(inputs[g], 0.0, 1.0);
    alphaTrial_[g] = architecture_->groups[g].activation.step(alpha_[g], inputTrial_[g], dt);
  }
  lambdaCTrial_ = lambdaC_;
  resetLambdaCStarts();
  externalLambdaCTrial_ = externalLambdaC_;
}

double MuscleHistory::trialActivationInputDerivative(int group) const {
  if (group < 0 || group >= static_cast<int>(alpha_.size()))
    throw std::out_of_range("MuscleHistory::trialActivationInputDerivative: no muscle group " + std::to_string(group));
  return trialActivationInputDerivative(group, inputTrial_[group]);
}

double MuscleHistory::trialActivationForInput(int group, double input) const {
  if (group < 0 || group >= static_cast<int>(alpha_.size()))
    throw std::out_of_range("MuscleHistory::trialActivationForInput: no muscle group " + std::to_string(group));
  return architecture_->groups[group].activation.step(alpha_[group], input, dt_);
}

double MuscleHistory::trialActivationInputDerivative(int group, double input) const {
  if (group < 0 || group >= static_cast<int>(alpha_.size()))
    throw std::out_of_range("MuscleHistory::trialActivationInputDerivative: no muscle group " + std::to_string(group));
  return architecture_->groups[group].activation.stepInputDerivative(alpha_[group], input, dt_);
}

void MuscleHistory::setTrialActivation(int group, double alpha) {
  if (group < 0 || group >= static_cast<int>(alpha_.size()))
    throw std::out_of_range("MuscleHistory::setTrialActivation: no muscle group " + std::to_string(group));
  alphaTrial_[group] = alpha;
}

materials::FamilyValues MuscleHistory::familyActivation(std::size_t i) const {
  const FibreRegion &region = architecture_->regions[region_[i]];
  materials::FamilyValues a(region.law->familyCount());
  for (int f = 0; f < a.size(); ++f) {
    const int g = region.familyGroup[f];
    a(f) = g < 0 ? 0.0 : alphaTrial_[g];
  }
  return a;
}

int MuscleHistory::familyCount(std::size_t i) const {
  return region_[i] < 0 ? 0 : architecture_->regions[region_[i]].law->familyCount();
}

const double *MuscleHistory::committedLambdaC(std::size_t i, int q) const {
  return lambdaC_.data() + offset_[i] + static_cast<std::size_t>(q * familyCount(i));
}

double *MuscleHistory::trialLambdaC(std::size_t i, int q) {
  return lambdaCTrial_.data() + offset_[i] + static_cast<std::size_t>(q * familyCount(i));
}

double *MuscleHistory::lambdaCStart(std::size_t i, int q) const {
  return lambdaCStart_.data() + 3 * (offset_[i] + static_cast<std::size_t>(q * familyCount(i)));
}

void MuscleHistory::resetLambdaCStarts() {
  lambdaCStart_.assign(3 * lambdaC_.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < offset_.size(); ++i) {
    const auto n = static_cast<std::size_t>(familyCount(i));
    for (std::size_t k = 0; k < 8 * n; ++k) {
      const std::size_t q = k / n, f = k % n;
      lambdaCStart_[3 * (offset_[i] + q * n) + f] = lambdaC_[offset_[i] + k];
    }
  }
}

void MuscleHistory::commit() {
  lambdaC_ = lambdaCTrial_;
  externalLambdaC_ = externalLambdaCTrial_;
  alpha_ = alphaTrial_;
  time_ = timeTrial_;
  ++revision_;
}

MuscleHistory::Snapshot MuscleHistory::snapshot() const {
  return {lambdaC_, alpha_, inputTrial_, externalLambdaC_, time_, dt_};
}

void MuscleHistory::restore(const Snapshot &state) {
  bool fits = state.lambdaC.size() == lambdaC_.size() && state.alpha.size() == alpha_.size() &&
              state.externalLambdaC.size() == externalLambdaC_.size();
  for (std::size_t m = 0; fits && m < externalLambdaC_.size(); ++m)
    fits = state.externalLambdaC[m].size() == externalLambdaC_[m].size();
  if (!fits) throw std::invalid_argument("MuscleHistory::restore: the state is another mesh's or partition's");
  lambdaC_ = lambdaCTrial_ = state.lambdaC;
  resetLambdaCStarts();
  alpha_ = alphaTrial_ = state.alpha;
  inputTrial_ = state.input;
  externalLambdaC_ = externalLambdaCTrial_ = state.externalLambdaC;
  time_ = timeTrial_ = state.time;
  dt_ = state.dt;
  ++revision_;
}

} // namespace glossa::model
