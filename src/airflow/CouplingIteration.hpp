#pragma once
// The partitioned coupling of the flow and the solid as a fixed point p = F(p) of the sections'
// pressures (doc/airflow.md, "Coupling"): F solves the solid under the face pressures mapped from
// p and returns the pressures the flow gives through the lumen it then has. Each iteration is told
// the iterate p_k and its image F(p_k) and returns p_{k+1}, by one of
//  - constant relaxation:  p_{k+1} = p_k + w r_k,  r_k = F(p_k) - p_k;
//  - Aitken's dynamic relaxation (Irons & Tuck 1969; Kuttler & Wall 2008): the same with
//      w_k = -w_{k-1} r_{k-1}.(r_k - r_{k-1}) / |r_k - r_{k-1}|^2,   w_0 the given relaxation;
//  - the interface quasi-Newton method with an approximate inverse Jacobian from a least-squares
//    model (IQN-ILS, Degroote, Bathe & Vierendeels 2009): the differences of the residuals
//    V = [r_k - r_i] and of the images W = [F(p_k) - F(p_i)] over this step's earlier iterates
//    i < k give alpha = argmin |V alpha + r_k|, and p_{k+1} = F(p_k) + W alpha (the first iteration
//    relaxes as above). A Newton iteration on the pressures whose Jacobian is learned from the
//    iterates: no derivative of the solid or the flow is needed;
//  - Newton's method with the Jacobian of F measured once a step (setJacobian: the solid's
//    response to each section's pressure through its tangent, then the flow's through the lumen;
//    solvers/run/AirflowCoupling): p_{k+1} = p_k - J^{-1} r_k with J = F' - I, and J updated by
//    Broyden's rank-one ("good") update from the iterates that follow, J += (dr - J dp) dp^T / |dp|^2,
//    so that the step's later solves sharpen a Jacobian taken at its first (Broyden 1965). Until a
//    Jacobian is set it relaxes as constant relaxation does.
// Eigen only.

#include <Eigen/Core>
#include <vector>

namespace glossa::airflow {

enum class CouplingMethod { constantRelaxation, aitken, quasiNewton, newton };

class CouplingIteration {
 public:
  // `relaxation` in (0, 1].
  CouplingIteration(CouplingMethod method, double relaxation);

  // Forgets the earlier iterates (a new step, or a retry of one).
  void restart();
  // The next iterate from p_k and F(p_k) (of the same size every call since restart()).
  Eigen::VectorXd next(const Eigen::VectorXd &iterate, const Eigen::VectorXd &image);
  // Newton's method: whether this step still needs its Jacobian (before the first next() that
  // can use it), and the Jacobian dF/dp of the map itself (square, of the pressures' size).
  bool needsJacobian() const { return method_ == CouplingMethod::newton && jacobian_.size() == 0; }
  void setJacobian(const Eigen::MatrixXd &mapJacobian);
  // The relaxation factor the last next() used (the quasi-Newton step's: 1 once it has a model).
  double lastRelaxation() const { return omega_; }

 private:
  CouplingMethod method_;
  double relaxation_;
  double omega_;
  int calls_ = 0;
  Eigen::VectorXd lastResidual_, lastIterate_;
  Eigen::MatrixXd jacobian_;  // Newton's J = F' - I, Broyden-updated; empty until set
  std::vector<Eigen::VectorXd> residuals_, images_;  // this step's, for IQN-ILS
};

}  // namespace glossa::airflow
