#pragma once
// The two parameter sets of the contractile element's curves (eq. 19-21, doc/materials.md):
//  - "paper-table-II": Table II exactly (with the closing factor as doc/materials.md resolves eq. 21;
//    f_cV term 1's amplitude is 2.5e-5). Reproduces the paper; its shapes contradict Fig. 4.
//  - "physiological" (the default): the same Gauss-mollifier family fitted by
//    materials/fit/fit_physiological_curves.py to Gordon, Huxley & Julian (1966) for f_cL and to
//    Hill's hyperbola (shortening) / van Soest & Bobbert's eccentric branch (lengthening) for
//    f_cV. Targets, fit and residuals: doc/materials.md.

#include <memory>
#include <string>

#include "materials/ForceCurve.hpp"

namespace glossa::materials {

struct ContractileCurves {
  std::shared_ptr<const ForceCurve> forceLength;    // f_cL(lambda_c)
  std::shared_ptr<const ForceCurve> forceVelocity;  // f_cV(d lambda_c / dt), rate in 1/s
};

ContractileCurves paperTableIICurves();
ContractileCurves physiologicalCurves();
// "paper-table-II" or "physiological"; throws std::invalid_argument naming both otherwise.
ContractileCurves contractileCurvesFromName(const std::string &name);
inline const char *defaultContractileCurveSet() { return "physiological"; }

}  // namespace glossa::materials
