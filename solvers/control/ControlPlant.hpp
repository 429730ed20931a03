#pragma once
// What the control driver needs of the solver at a control step, and no more: solve the
// step from the committed state with given neural inputs, keep the state of the candidate that
// beats every earlier one (so the winner is at hand when the search ends, without another
// solve), the sensitivity of the control points to the inputs at that kept state, and the kept
// state as a flat buffer to share among control groups. Without Trilinos, so that a fake plant
// (e.g. a linear one, x = x0 + A u) can test the driver.

#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "solvers/nonlinear/SolveStatistics.hpp"

namespace glossa::solvers {

// One candidate's step solve from the committed state.
struct CandidateSolve {
  bool ok = false;
  std::string why;                   // when not ok
  bool screened = false;             // not ok: a GA candidate's moved start turned an element over, not retried
  bool solvedAgain = false;          // its moved start failed; it was solved again from the step's start
  Eigen::Matrix3Xd pointDisplacement; // when ok: one column per control point
  UzawaResult statistics;
  // With an airflow (doc/airflow.md): the candidate's coupling iterations and the largest change
  // of a section's pressure at the last (0 and 0 without one).
  int couplingIterations = 0;
  double couplingChange = 0.0;
  // With the controller's airway term (ControllerParameters::airwayWeight > 0): the smallest
  // lumen area at the candidate's state [m^2]; NaN when not measured (no term, or no section).
  double smallestArea = std::numeric_limits<double>::quiet_NaN();
};

// d x_p / d u_M at the kept state: 3 rows per point (x, y, z), one column per group asked.
struct InputSensitivity {
  Eigen::MatrixXd dxdu;
  int krylovIterations = 0;
  // With the airway term: d A / d u_M of the kept state's smallest section, one per group asked
  // (empty without the term).
  Eigen::RowVectorXd dAdu;
  // Why it could not be computed (its tangent solve failed); empty when it was. dxdu is empty then.
  std::string failure;
};

class ControlPlant {
public:
  virtual ~ControlPlant() = default;

  // Solves the step with `inputs` (one per muscle group of the scene; those of uncontrolled
  // groups are ignored) from the committed state. The solve's state is the plant's "last".
  virtual CandidateSolve solve(const std::vector<double> &inputs) = 0;
  // Keeps the last solve's state, replacing what was kept.
  virtual void keepLast() = 0;

  // At the kept state, which was solved with `inputs`, for the groups `groups` (scene indices). A
  // failed tangent solve is reported in `failure`, not thrown, and alike on every rank.
  virtual InputSensitivity sensitivity(const std::vector<double> &inputs, const std::vector<int> &groups) = 0;
  // The kept state as numbers, and back: a control group adopts the winning group's state.
  // Collective on the plant's own communicator.
  virtual std::vector<double> packKept() const = 0;
  virtual void unpackKept(const std::vector<double> &state) = 0;
};

} // namespace glossa::solvers
