#pragma once
// The active muscle point law (doc/theory.md, eq. 2-6, 11-18): an isochoric matrix (the Fung
// muscle matrix, eq. 10) and any number of Hill fibre families, each with a reference direction
// N_f, a volume fraction phi_f and its own Hill fibre (the T0s and curve set of its muscle group).
// Each family's fibre stretch is lambda-bar_f = sqrt(N_f . C-bar N_f) and its tension T_f comes
// from HillMuscleFibre, so the stress is P = w_M P_M + sum_f phi_f T_f d lambda-bar_f / dF (plus the
// eq. 5 term if chosen; stress forms as in FibreComposite.hpp).
//
// History dependent, therefore its own interface: evaluate() is pure and const; the caller keeps
// lambda_c per family (old/new pairs), commits `lambdaC` when a step converges and discards it
// when the step fails. Fixed capacity (no heap allocation per call): at most kMaxFibreFamilies.

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "materials/FibreComposite.hpp"
#include "materials/FibreFamily.hpp"
#include "materials/HillMuscleFibre.hpp"
#include "materials/IsochoricMaterial.hpp"

namespace glossa::materials {

constexpr int kMaxFibreFamilies = 8;
// Per-family values, dynamic size <= kMaxFibreFamilies, stored inline.
using FamilyValues = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxFibreFamilies, 1>;
// Per-family reference directions as columns, stored inline.
using FamilyDirections = Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::ColMajor, 3, kMaxFibreFamilies>;

struct MusclePointInput {
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  double dt = 1.0;          // time step [s]
  FamilyValues alpha;       // activation of each family's muscle group, in [0, 1]
  FamilyValues lambdaCOld;  // committed contractile stretch per family
  FamilyValues lambdaCStart; // where each family's local solve starts (empty: lambdaCOld)
  // With lambdaCStart, the fibre stretch it was the root at and d lambda_c / d lambda_f there
  // (empty or NaN: none): the solve starts from lambdaCStart + slope (lambda_f - lambdaFAtStart),
  // the root to first order.
  FamilyValues lambdaFAtStart, startSlope;
  // Reference fibre directions at this point (unit columns, one per family) when the direction
  // varies over the body (a fan, a field read from a file); empty: each family's own N.
  FamilyDirections directions;
};

struct MusclePointResponse {
  double energy = 0.0;  // stored elastic energy: w_M psi_M + sum phi_f (psi_p + psi_s) [J/m^3]
  Eigen::Matrix3d P = Eigen::Matrix3d::Zero();
  Tangent9 dPdF = Tangent9::Zero();
  FamilyValues lambdaC;  // new contractile stretch per family (commit on convergence)
  FamilyValues lambdaF;  // isochoric fibre stretch per family
  FamilyValues T;        // fibre tension T_f per family [Pa]
  FamilyValues dLambdaCdLambdaF;  // of each family's root (NaN unless found by the taut solve)
  HillSolveStatus status = HillSolveStatus::Taut;  // the first failure, else Taut (any family
                                                   // pulling) or Slack
  int failedFamily = -1;                           // index of the family that failed, -1 if none
  bool ok() const { return failedFamily < 0; }
};

class MuscleMaterial {
 public:
  struct Family {
    FibreFamily geometry;
    HillMuscleFibre fibre;
  };

  // Throws std::invalid_argument on a null matrix, invalid families or more than
  // kMaxFibreFamilies families.
  MuscleMaterial(std::shared_ptr<const IsochoricMaterial> matrix, std::vector<Family> families,
                 MatrixStressForm form = MatrixStressForm::InFull);

  // Requires det F > 0, alpha and lambdaCOld sized familyCount() and directions empty or with
  // familyCount() columns; otherwise status InvalidInput.
  MusclePointResponse evaluate(const MusclePointInput &in) const;

  int familyCount() const { return static_cast<int>(families_.size()); }
  const std::vector<Family> &families() const { return families_; }
  double matrixFraction() const { return matrixFraction_; }
  double shearModulus() const { return matrixWeight(form_, matrixFraction_) * matrix_->shearModulus(); }
  MatrixStressForm stressForm() const { return form_; }
  // Initial history: lambda_c = 1 (the zero-strain configuration is the optimal length).
  FamilyValues initialLambdaC() const { return FamilyValues::Ones(familyCount()); }

 private:
  std::shared_ptr<const IsochoricMaterial> matrix_;
  std::vector<Family> families_;
  MatrixStressForm form_;
  double matrixFraction_;
};

}  // namespace glossa::materials
