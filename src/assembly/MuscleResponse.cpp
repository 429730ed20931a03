#include "assembly/MuscleResponse.hpp"

#include <limits>

#include <Teuchos_CommHelpers.hpp>

#include "assembly/TimeSplit.hpp"
#include "control/MusclePruning.hpp"
#include "fem/HexShape.hpp"
#include "model/TissuePointLaw.hpp"

namespace glossa::assembly {

MuscleFields updateMuscleHistory(const ResultEvaluator &results, const Vector &u, model::MuscleHistory &history) {
  const PartTimer timer(TimedPart::muscleHistory);
  const model::Scene &scene = results.scene();
  const DistributedLayout &layout = results.assembler().layout();
  const auto &localElements = layout.localElements;
  const mesh::HexMesh &mesh = scene.mesh;
  const auto &muscles = scene.muscles;
  MuscleFields out;
  const std::size_t n = localElements.size();
  const std::size_t G = muscles.groups.size();
  out.groups = static_cast<int>(G);
  out.fibreStretch.assign(n * G, 0.0);
  out.contractileStretch.assign(n * G, 0.0);
  out.fibreStress.assign(n, 0.0);
  // Per group: sums of lambda_f w, lambda_c w and w (then reduced over ranks), w the fibre length
  // a point carries: L_f of the element along the family's reference direction (§6.1's
  // length-weighted average fibre stretch, control::fibreLengthMeasure) times the point's share
  // of the element's reference volume.
  std::vector<double> weighted(3 * G, 0.0), weightedAll(3 * G, 0.0);
  int localValid = 1;
  Vector uOverlap(results.overlapMap());
  results.importToOverlap(u, uOverlap);
  auto uData = uOverlap.getData(0);
  if (muscles.hasFibres()) {
    for (std::size_t i = 0; i < n; ++i) {
      const auto e = static_cast<std::size_t>(localElements[i]);
      const int region = muscles.elementRegion[e];
      if (region < 0) continue;
      const model::FibreRegion &r = muscles.regions[region];
      const fem::NodeMatrix X = mesh.elementCoordinates(localElements[i]);
      const fem::NodeMatrix ue = results.elementDisplacement(i, uData);
      std::array<Eigen::Matrix3d, 8> F;
      std::array<double, 8> dV;
      std::array<const double *, 8> lambdaCOld;
      std::array<double *, 8> lambdaCStart; // the converged iterate's roots: found at once
      for (int q = 0; q < 8; ++q) {
        lambdaCOld[q] = history.committedLambdaC(i, q);
        lambdaCStart[q] = history.lambdaCStart(i, q);
      }
      model::ElementMuscleResponse evaluated;
      bool ok = fem::quadratureDeformationGradients(X, ue, F, dV);
      // The last Newton pass was usually at this state: what its point laws computed is kept.
      const model::ElementMuscleResponse *kept = ok ? results.keptMuscleResponse(i, ue) : nullptr;
      if (!kept) {
        const model::TissuePointLaw law(*r.law, muscles.directions[e], history.familyActivation(i), history.dt(),
                                        lambdaCOld, &evaluated, muscles.pointDirectionsOf(e), lambdaCStart);
        materials::PointResponse ignored;
        for (int q = 0; ok && q < 8; ++q) ok = F[q].determinant() > 0.0 && law.evaluate(q, F[q], ignored);
      }
      const model::ElementMuscleResponse &response = kept ? *kept : evaluated;
      if (!ok) {
        localValid = 0;
        continue;
      }
      const int families = r.law->familyCount();
      std::vector<int> count(G, 0);
      double volume = 0.0;
      for (int q = 0; q < 8; ++q) volume += dV[q];
      std::vector<double> fibreLength(static_cast<std::size_t>(families), 0.0);
      for (int f = 0; f < families; ++f)
        if (r.familyGroup[f] >= 0) fibreLength[f] = control::fibreLengthMeasure(X, muscles.directions[e].col(f));
      for (int q = 0; q < 8; ++q) {
        double* lambdaC = history.trialLambdaC(i, q);
        for (int f = 0; f < families; ++f) {
          lambdaC[f] = response.lambdaC[q](f);
          out.fibreStress[i] += r.law->families()[f].geometry.volumeFraction * response.T[q](f) / 8.0;
          const int g = r.familyGroup[f];
          if (g < 0) continue;
          out.fibreStretch[i * G + g] += response.lambdaF[q](f);
          out.contractileStretch[i * G + g] += response.lambdaC[q](f);
          ++count[g];
          const double w = fibreLength[f] * dV[q] / volume;
          weighted[3 * g] += response.lambdaF[q](f) * w;
          weighted[3 * g + 1] += response.lambdaC[q](f) * w;
          weighted[3 * g + 2] += w;
        }
      }
      for (std::size_t g = 0; g < G; ++g)
        if (count[g] > 0) {
          out.fibreStretch[i * G + g] /= count[g];
          out.contractileStretch[i * G + g] /= count[g];
        }
    }
  }
  // The external fibres' lambda_c at the converged u (their forces are not needed here).
  std::vector<double> external(3 * G, 0.0), externalAll(3 * G, 0.0);
  if (const ExternalMuscleForces *externals = results.externalMuscles())
    if (!externals->evaluate(results.loadTarget(uData, nullptr, nullptr, false), &history, &external)) localValid = 0;
  int globalValid = 0;
  Teuchos::reduceAll(*layout.comm(), Teuchos::REDUCE_MIN, localValid, Teuchos::outArg(globalValid));
  out.valid = globalValid == 1;
  if (G > 0) {
    Teuchos::reduceAll(*layout.comm(), Teuchos::REDUCE_SUM, static_cast<int>(3 * G), weighted.data(), weightedAll.data());
    Teuchos::reduceAll(*layout.comm(), Teuchos::REDUCE_SUM, static_cast<int>(3 * G), external.data(), externalAll.data());
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t g = 0; g < G; ++g) {
    // Internal families first; a group with external fibres only has theirs; one with neither
    // has no stretch to report (NaN, doc/output.md).
    const double length = weightedAll[3 * g + 2], externalLength = externalAll[3 * g + 2];
    const double *sums = length > 0.0 ? &weightedAll[3 * g] : &externalAll[3 * g];
    const double L = length > 0.0 ? length : externalLength;
    out.groupMeanStretch.push_back(L > 0.0 ? sums[0] / L : nan);
    out.groupMeanContractileStretch.push_back(L > 0.0 ? sums[1] / L : nan);
  }
  return out;
}

} // namespace glossa::assembly
