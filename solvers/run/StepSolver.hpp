#pragma once
// One load step's solve and the checks its converged state must pass: the Uzawa loop of Newton
// solves at the step's time (UzawaLoop), the muscle history at the converged state, the smallest
// corner det F (reported), the refusal of a state with an element folded through itself, and of
// a state that has passed through a symmetry plane.

#include <vector>

#include "solvers/incompressibility/UzawaLoop.hpp"
#include "solvers/linear/LinearSolverFactory.hpp"
#include "solvers/run/StepState.hpp"

namespace glossa::assembly {
class Assembler;
class ModelEvaluator;
} // namespace glossa::assembly
namespace glossa::model {
class MuscleHistory;
struct Scene;
struct SymmetryPlane;
} // namespace glossa::model

namespace glossa::solvers {

class AirflowCoupling;
class NewtonSolver;
class UzawaLoop;

// The solver stack a step solve drives (owned by the run's set-up).
struct StepSolverParts {
  const assembly::Assembler &assembler;
  assembly::ModelEvaluator &model;
  NewtonSolver &newton;
  const UzawaLoop &uzawa;
  model::MuscleHistory &history;
  const AirflowCoupling *airflow = nullptr; // a scene with airflow: every solve is coupled to it
};

class StepSolver {
public:
  // `keptScope`: how long Newton keeps its linear solver (a step's: forgotten before each
  // solve). `progress`: a line per Newton and Uzawa iteration on the console; `talk`: the notes
  // (a tissue's kappa_AL raised).
  StepSolver(const StepSolverParts &parts, const model::Scene &scene, ReuseScope keptScope, bool progress,
             bool talk = false);
  ~StepSolver();

  // Solves from `state` (the start on entry) to `time` into `state`; the muscle history's trial
  // values are this step's, at the neural inputs `inputs` (one per muscle group; empty: the
  // deck's u(t)), which reach the model as its p2. `quiet`: no per-iteration output (a
  // controller's candidates). With airflow, the solve is coupled to the flow (AirflowCoupling):
  // the solid is solved once per coupling iteration, from the last. `loadScale` [N]: the least
  // force the Newton tolerance is relative to (it is also relative to the external force and the
  // first residual; StepAttempt::loadScale): a start close to the solution, whose first residual
  // is small, is then solved to the tolerance of the solve it was predicted from. Collective.
  StepAttempt solve(double time, double dt, StepState &state, bool quiet, const std::vector<double> &inputs = {},
                    double loadScale = 0.0) const;
  // A converged state in which material has crossed a symmetry plane is refused
  // (model/SymmetryPlanes.hpp): `attempt` then fails, saying where. Collective.
  void refuseInsideOut(const StepState &state, StepAttempt &attempt) const;
  // The corner checks of a converged state (ResultEvaluator::worstCorner) into `attempt`; an
  // element turned over by more than fem::kFoldedFraction of its volume refuses the state, which
  // `attempt.folded` then names (the run stops there: a smaller step reaches the same fold).
  // Collective.
  void measureCorners(const StepState &state, double time, StepAttempt &attempt) const;

private:
  // One solve of the solid under the loads as they stand; `outer`: a condition iterated in its
  // Uzawa loop (the airflow's coupling).
  StepAttempt solveSolid(double time, double dt, StepState &state, bool quiet, const std::vector<double> &inputs,
                         double loadScale, const UzawaLoop::OuterCondition &outer = {}) const;
  // The step coupled to the airflow, around whole solid solves or inside their Uzawa loop.
  StepAttempt solveCoupledAroundSolves(double time, double dt, StepState &state, bool quiet,
                                       const std::vector<double> &inputs, double loadScale) const;
  StepAttempt solveCoupledInUzawaLoop(double time, double dt, StepState &state, bool quiet,
                                      const std::vector<double> &inputs, double loadScale) const;

  // The displacement of every node per pascal on each airflow section's faces at the solved state
  // u: the tangent at u solved for the airflow load of each section alone (Newton's coupling
  // method, AirflowCoupling). Collective.
  std::vector<std::vector<double>> sectionResponses(const assembly::Vector &u, double time) const;
  // Their solves' relative tolerance: a Jacobian of the coupling needs a few digits (its update is
  // tested by the coupling's own residual).
  static constexpr double kResponseTolerance = 1e-2;

  StepSolverParts parts_;
  const model::Scene &scene_;
  ReuseScope keptScope_;
  bool progress_, talk_;
  std::vector<model::SymmetryPlane> planes_;
  double lengthScale_ = 0.0; // the largest |X| of the mesh
};

} // namespace glossa::solvers
