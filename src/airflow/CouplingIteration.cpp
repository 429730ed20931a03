#include "airflow/CouplingIteration.hpp"

#include <Eigen/LU>
#include <Eigen/QR>
#include <cmath>
#include <stdexcept>

namespace glossa::airflow {

CouplingIteration::CouplingIteration(CouplingMethod method, double relaxation)
    : method_(method), relaxation_(relaxation), omega_(relaxation) {
  if (!(relaxation > 0.0 && relaxation <= 1.0))
    throw std::invalid_argument("coupling iteration: the relaxation must lie in (0, 1]");
}

void CouplingIteration::restart() {
  calls_ = 0;
  omega_ = relaxation_;
  residuals_.clear();
  images_.clear();
  jacobian_.resize(0, 0);
}

void CouplingIteration::setJacobian(const Eigen::MatrixXd &mapJacobian) {
  if (mapJacobian.rows() != mapJacobian.cols())
    throw std::invalid_argument("coupling iteration: the map's Jacobian must be square");
  jacobian_ = mapJacobian - Eigen::MatrixXd::Identity(mapJacobian.rows(), mapJacobian.cols());
  calls_ = 0; // Broyden's updates start from this Jacobian
}

Eigen::VectorXd CouplingIteration::next(const Eigen::VectorXd &iterate, const Eigen::VectorXd &image) {
  const Eigen::VectorXd r = image - iterate;
  if (method_ == CouplingMethod::quasiNewton) {
    residuals_.push_back(r);
    images_.push_back(image);
    const std::size_t k = residuals_.size() - 1;
    if (k == 0) {
      omega_ = relaxation_;
      return iterate + omega_ * r;
    }
    Eigen::MatrixXd V(r.size(), static_cast<Eigen::Index>(k)), W(r.size(), static_cast<Eigen::Index>(k));
    for (std::size_t i = 0; i < k; ++i) {
      V.col(static_cast<Eigen::Index>(i)) = r - residuals_[i];
      W.col(static_cast<Eigen::Index>(i)) = image - images_[i];
    }
    // The least-squares coefficients with the smallest norm: columns that have become dependent
    // (more iterates than the pressures vary in) add nothing instead of blowing up.
    const Eigen::VectorXd alpha = V.completeOrthogonalDecomposition().solve(-r);
    omega_ = 1.0;
    return image + W * alpha;
  }
  if (method_ == CouplingMethod::newton && jacobian_.size() != 0) {
    if (jacobian_.rows() != r.size()) throw std::invalid_argument("coupling iteration: the Jacobian's size is not the pressures'");
    if (calls_ > 0) {
      const Eigen::VectorXd dp = iterate - lastIterate_;
      const double dp2 = dp.squaredNorm();
      if (dp2 > 0.0) jacobian_ += ((r - lastResidual_) - jacobian_ * dp) * dp.transpose() / dp2;
    }
    ++calls_;
    lastResidual_ = r;
    lastIterate_ = iterate;
    omega_ = 1.0;
    return iterate - jacobian_.fullPivLu().solve(r);
  }
  if (method_ == CouplingMethod::aitken && calls_ > 0) {
    const Eigen::VectorXd dr = r - lastResidual_;
    const double dr2 = dr.squaredNorm();
    // Unchanged residuals (a converged or a stalled pair) keep the last factor.
    if (dr2 > 0.0) omega_ = -omega_ * lastResidual_.dot(dr) / dr2;
  }
  ++calls_;
  lastResidual_ = r;
  return iterate + omega_ * r;
}

}  // namespace glossa::airflow
