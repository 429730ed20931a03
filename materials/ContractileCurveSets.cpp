#include "materials/ContractileCurveSets.hpp"

#include <stdexcept>

#include "materials/GaussMollifierCurve.hpp"

namespace glossa::materials {

namespace {

// Eq. 19 and 20: f_cL on [0.5, 2], 0 outside; f_cV on [-10, 10], 0 below, 1.5 above.
std::shared_ptr<const ForceCurve> forceLength(std::vector<GaussMollifierTerm> terms) {
  return std::make_shared<GaussMollifierCurve>(std::move(terms), 0.5, 2.0, 0.0, 0.0);
}
std::shared_ptr<const ForceCurve> forceVelocity(std::vector<GaussMollifierTerm> terms) {
  return std::make_shared<GaussMollifierCurve>(std::move(terms), -10.0, 10.0, 0.0, 1.5);
}

}  // namespace

// Table II; columns mu, p, A, B, R, q, s.
ContractileCurves paperTableIICurves() {
  return {
      forceLength(
          {{0.8, 2, 0.475, 90, 1, 4, 8}, {1.3, 2, 0.100, 10, 1, 2, 8}, {1.325, 1, 4830.635, 3, 0.75, 4, 8}}),
      forceVelocity({{-0.75, 2, 2.5e-5, 0.01, 10, 2, 2},
                     {-0.6, 2, 0.3, 0.25, 0, 0, 0},
                     {0.55, 2, 0.425, 0.7, 0, 0, 0},
                     {1.4, 4, 0.1, 0.3, 0, 0, 0},
                     {0.75, 8, 0.525, 15, 0, 0, 0}})};
}

// Printed by materials/fit/fit_physiological_curves.py (doc/materials.md has its residuals).
ContractileCurves physiologicalCurves() {
  return {
      forceLength(
          {{0.76974827637139787, 2, 47.019759707767413, 47.967654031992367, 0.26973032141231235, 2, 2},
           {1.0047595921007841, 2, 23.698624336369299, 0.67475292919121743, 0.45309402670273086, 2, 2},
           {1.406989899346859, 2, 15.44428827333468, 11.424809396699828, 0.40699034083304425, 2, 2}}),
      forceVelocity(
          {{10, 2, 0.0037499999999999999, 0.0061173379483261585, 20, 2, 1},
           {-1.3808339783681967, 2, -0.00067709028557778688, 0.017631402797187161, 4.3350505085354447, 2, 2},
           {1.4102260259140635, 2, 0.00010703095282650308, 0.021123897812346661, 8.2662066946156703, 2, 2},
           {0.84590345431063696, 2, 5.4498058135117555e-05, 0.80461350062269776, 8.032999019866601, 2, 2}})};
}

ContractileCurves contractileCurvesFromName(const std::string &name) {
  if (name == "paper-table-II") return paperTableIICurves();
  if (name == "physiological") return physiologicalCurves();
  throw std::invalid_argument("unknown contractile curve set '" + name + "' (paper-table-II, physiological)");
}

}  // namespace glossa::materials
