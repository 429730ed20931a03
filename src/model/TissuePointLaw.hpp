#pragma once
// The point law of one element carrying muscle fibres, as the element kernel sees it
// (fem::QuadraturePointLaw): the region's MuscleMaterial with the element's fibre directions (or one set per point),
// its groups' trial activation, the step size and each point's committed lambda_c. Optionally
// records what the point law computed (new lambda_c, fibre stretch and tension per family) for
// the history update and the output; Newton iterations leave those null.

#include <array>

#include "fem/QuadraturePointLaw.hpp"
#include "materials/MuscleMaterial.hpp"

namespace glossa::model {

// What the point law computed at the 8 points of an element.
struct ElementMuscleResponse {
  std::array<materials::FamilyValues, 8> lambdaC, lambdaF, T;
  materials::HillSolveStatus status = materials::HillSolveStatus::Taut;
};

class TissuePointLaw final : public fem::QuadraturePointLaw {
public:
  // `lambdaCOld(q)` points at familyCount() committed values for point q.
  // `pointDirections`, when not null, gives the directions per point (the element's directions
  // varying inside it) and replaces `directions`.
  // `lambdaCStart(q)`, when given, points at 3 x familyCount() values: the last roots of point q's
  // local solves, the fibre stretches at them and their slopes d lambda_c / d lambda_f, where the
  // next solves start; it receives the new ones (MuscleHistory::lambdaCStart).
  TissuePointLaw(const materials::MuscleMaterial &law, const materials::FamilyDirections &directions,
                 const materials::FamilyValues &alpha, double dt,
                 std::array<const double *, 8> lambdaCOld, ElementMuscleResponse *record = nullptr,
                 const std::array<materials::FamilyDirections, 8> *pointDirections = nullptr,
                 std::array<double *, 8> lambdaCStart = {})
      : law_(law), lambdaCOld_(lambdaCOld), lambdaCStart_(lambdaCStart), record_(record),
        pointDirections_(pointDirections) {
    input_.directions = directions;
    input_.alpha = alpha;
    input_.dt = dt;
  }

  bool evaluate(int q, const Eigen::Matrix3d &F, materials::PointResponse &out) const override {
    const int n = law_.familyCount();
    input_.F = F;
    if (pointDirections_) input_.directions = (*pointDirections_)[static_cast<std::size_t>(q)];
    input_.lambdaCOld = Eigen::Map<const Eigen::VectorXd>(lambdaCOld_[q], n);
    double *start = lambdaCStart_[static_cast<std::size_t>(q)];
    if (start) {
      input_.lambdaCStart = Eigen::Map<const Eigen::VectorXd>(start, n);
      input_.lambdaFAtStart = Eigen::Map<const Eigen::VectorXd>(start + n, n);
      input_.startSlope = Eigen::Map<const Eigen::VectorXd>(start + 2 * n, n);
    }
    const materials::MusclePointResponse r = law_.evaluate(input_);
    if (start && r.ok()) {
      Eigen::Map<Eigen::VectorXd>(start, n) = r.lambdaC;
      Eigen::Map<Eigen::VectorXd>(start + n, n) = r.lambdaF;
      Eigen::Map<Eigen::VectorXd>(start + 2 * n, n) = r.dLambdaCdLambdaF;
    }
    if (record_) {
      record_->lambdaC[q] = r.lambdaC;
      record_->lambdaF[q] = r.lambdaF;
      record_->T[q] = r.T;
      if (!r.ok()) record_->status = r.status;
    }
    if (!r.ok()) return false;
    out.energy = r.energy;
    out.P = r.P;
    out.dPdF = r.dPdF;
    return true;
  }

private:
  const materials::MuscleMaterial &law_;
  mutable materials::MusclePointInput input_;
  std::array<const double *, 8> lambdaCOld_;
  std::array<double *, 8> lambdaCStart_;
  ElementMuscleResponse *record_;
  const std::array<materials::FamilyDirections, 8> *pointDirections_;
};

} // namespace glossa::model
