#pragma once
// A fake plant for the control driver: the control points move linearly with the inputs,
// d = A u (3 rows per point, one column per muscle group), so every objective is known in closed
// form. A candidate can be made to fail; the kept state is the kept candidate's inputs, and its
// statistics carry the inputs too, so a test can tell whose state and statistics won.

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "solvers/control/ControlPlant.hpp"

namespace glossa::test {

class LinearPlant final : public solvers::ControlPlant {
public:
  explicit LinearPlant(Eigen::MatrixXd A) : A_(std::move(A)) {}

  // Inputs for which the solve fails.
  std::function<bool(const std::vector<double> &)> fails = [](const std::vector<double> &) { return false; };
  // Of the failing inputs, those reported as screened (CandidateSolve::screened).
  std::function<bool(const std::vector<double> &)> screens = [](const std::vector<double> &) { return false; };
  // Inputs reported as solved twice (CandidateSolve::solvedAgain), failing or not.
  std::function<bool(const std::vector<double> &)> solvesAgain = [](const std::vector<double> &) {
    return false;
  };
  // The sensitivity reported is this times the true one (1: exact).
  double sensitivityScale = 1.0;
  // Every sensitivity fails (as a tangent solve that did not converge), with this reason.
  std::string sensitivityFailure;
  // A lumen whose smallest area is affine in the inputs, A(u) = area0 + areaRate . u [m^2]
  // (NaN area0: no lumen); its reported dA/du is areaSensitivityScale times the true one.
  double area0 = std::numeric_limits<double>::quiet_NaN();
  Eigen::RowVectorXd areaRate;
  double areaSensitivityScale = 1.0;
  double area(const std::vector<double> &inputs) const {
    return area0 + areaRate.dot(Eigen::Map<const Eigen::VectorXd>(inputs.data(), static_cast<Eigen::Index>(inputs.size())));
  }
  int solves = 0;
  std::vector<std::vector<double>> solved; // the inputs of every solve, in order

  Eigen::Matrix3Xd displacement(const std::vector<double> &inputs) const {
    const Eigen::VectorXd d = A_ * Eigen::Map<const Eigen::VectorXd>(inputs.data(), static_cast<Eigen::Index>(inputs.size()));
    return Eigen::Map<const Eigen::Matrix3Xd>(d.data(), 3, d.size() / 3);
  }

  solvers::CandidateSolve solve(const std::vector<double> &inputs) override {
    ++solves;
    solved.push_back(inputs);
    last_ = inputs;
    solvers::CandidateSolve out;
    out.ok = !fails(inputs);
    out.solvedAgain = solvesAgain(inputs);
    if (!out.ok) {
      out.why = "the fake solve failed";
      out.screened = screens(inputs);
      return out;
    }
    out.pointDisplacement = displacement(inputs);
    if (std::isfinite(area0)) out.smallestArea = area(inputs);
    out.statistics.converged = true;
    out.statistics.solves = 1;
    solvers::NewtonResult n;
    n.converged = true;
    n.residualNorms = inputs;
    out.statistics.newton.push_back(n);
    return out;
  }

  void keepLast() override { kept_ = last_; }

  solvers::InputSensitivity sensitivity(const std::vector<double> &inputs, const std::vector<int> &groups) override {
    if (inputs != kept_) throw std::logic_error("LinearPlant: sensitivity away from the kept state");
    solvers::InputSensitivity s;
    if (!sensitivityFailure.empty()) {
      s.failure = sensitivityFailure;
      return s;
    }
    s.dxdu.resize(A_.rows(), static_cast<Eigen::Index>(groups.size()));
    for (std::size_t j = 0; j < groups.size(); ++j) s.dxdu.col(static_cast<Eigen::Index>(j)) = sensitivityScale * A_.col(groups[j]);
    s.krylovIterations = static_cast<int>(groups.size());
    if (std::isfinite(area0)) {
      s.dAdu.resize(static_cast<Eigen::Index>(groups.size()));
      for (std::size_t j = 0; j < groups.size(); ++j)
        s.dAdu(static_cast<Eigen::Index>(j)) = areaSensitivityScale * areaRate(groups[j]);
    }
    return s;
  }

  std::vector<double> packKept() const override { return kept_; }
  void unpackKept(const std::vector<double> &state) override { kept_ = state; }
  const std::vector<double> &kept() const { return kept_; }

private:
  Eigen::MatrixXd A_;
  std::vector<double> last_, kept_;
};

} // namespace glossa::test
