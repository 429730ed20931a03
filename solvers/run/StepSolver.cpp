#include "solvers/run/StepSolver.hpp"

#include <cstdio>

#include "assembly/Assembler.hpp"
#include "assembly/LoadContribution.hpp"
#include "assembly/ModelEvaluator.hpp"
#include "assembly/ResultEvaluator.hpp"
#include "fem/TurnedOverVolume.hpp"
#include "model/Scene.hpp"
#include "model/SymmetryPlanes.hpp"
#include "solvers/incompressibility/UzawaLoop.hpp"
#include "solvers/linear/MumpsPreconditioner.hpp"
#include "solvers/nonlinear/NewtonSolver.hpp"
#include "solvers/run/AirflowCoupling.hpp"

namespace glossa::solvers {

StepSolver::StepSolver(const StepSolverParts &parts, const model::Scene &scene, ReuseScope keptScope, bool progress,
                       bool talk)
    : parts_(parts), scene_(scene), keptScope_(keptScope), progress_(progress), talk_(talk),
      planes_(model::findSymmetryPlanes(scene.mesh, scene.dirichlet)) {
  for (const auto &x : scene.mesh.nodes) lengthScale_ = std::max(lengthScale_, x.norm());
}

StepSolver::~StepSolver() = default;

namespace {
// Why a step solve failed, from its statistics.
std::string failureReason(const StepAttempt &a) {
  const UzawaResult &r = a.uzawa;
  const NewtonResult &last = r.newton.back();
  return !a.muscle.valid ? "a contractile-stretch solve failed at the converged state"
         : r.elementInverted ? "an element inverted (J <= 0) or a muscle point law failed"
         : !last.failure.empty() ? last.failure.substr(0, last.failure.find('\n'))
         : !last.converged ? "Newton did not converge"
         : !r.gapMet()     ? "Uzawa did not reach a contact's gap tolerance"
                           : "Uzawa did not reach the dilatation tolerance";
}
} // namespace

StepAttempt StepSolver::solve(double time, double dt, StepState &state, bool quiet,
                              const std::vector<double> &inputs, double loadScale) const {
  if (!parts_.airflow) return solveSolid(time, dt, state, quiet, inputs, loadScale);
  return parts_.airflow->parameters().loop == input::AirflowLoop::uzawaLoop
             ? solveCoupledInUzawaLoop(time, dt, state, quiet, inputs, loadScale)
             : solveCoupledAroundSolves(time, dt, state, quiet, inputs, loadScale);
}

namespace {
// A step whose solid converged but whose coupling did not (or whose flow failed) fails with the
// coupling's reason; the coupling's outcome goes with the attempt.
void takeCoupling(const AirflowStep &coupled, StepAttempt &attempt) {
  attempt.airflow = coupled;
  if (coupled.converged) return;
  attempt.ok = false;
  // A Newton solve that failed is the reason (solveSolid said why).
  if (!attempt.uzawa.newton.empty() && !attempt.uzawa.newton.back().converged) return;
  attempt.why = !coupled.why.empty() ? coupled.why
                                     : "the airflow coupling did not converge within 'maximum Uzawa iterations' "
                                       "Newton solves";
}
} // namespace

StepAttempt StepSolver::solveCoupledInUzawaLoop(double time, double dt, StepState &state, bool quiet,
                                                const std::vector<double> &inputs, double loadScale) const {
  const assembly::ResultEvaluator results(parts_.assembler);
  AirflowCoupling::StepCoupling coupling(*parts_.airflow, time, results.gatherDisplacement(state.u),
                                         progress_ && !quiet);
  StepAttempt out;
  if (!coupling.started()) {
    takeCoupling(coupling.result(), out);
    return out;
  }
  const UzawaLoop::OuterCondition outer = [&](const assembly::Vector &u) {
    switch (coupling.afterSolve(results.gatherDisplacement(u), [&] { return sectionResponses(u, time); })) {
    case AirflowCoupling::StepCoupling::Verdict::coupled: return UzawaLoop::OuterVerdict::met;
    case AirflowCoupling::StepCoupling::Verdict::again: return UzawaLoop::OuterVerdict::updated;
    default: return UzawaLoop::OuterVerdict::failed;
    }
  };
  out = solveSolid(time, dt, state, quiet, inputs, loadScale, outer);
  takeCoupling(coupling.result(), out);
  return out;
}

StepAttempt StepSolver::solveCoupledAroundSolves(double time, double dt, StepState &state, bool quiet,
                                                 const std::vector<double> &inputs, double loadScale) const {
  const assembly::ResultEvaluator results(parts_.assembler);
  StepAttempt last;
  UzawaResult counted; // the coupling's earlier solves, added to the last one's counts
  const AirflowStep coupled = parts_.airflow->couple(
      time, results.gatherDisplacement(state.u),
      [&](std::vector<double> &uAll) {
        if (!last.uzawa.newton.empty()) {
          counted.solves += last.uzawa.solves;
          counted.newtonIterations += last.uzawa.newtonIterations;
          counted.linearIterations += last.uzawa.linearIterations;
          counted.contactUpdates += last.uzawa.contactUpdates;
        }
        last = solveSolid(time, dt, state, quiet, inputs, loadScale);
        if (last.ok) uAll = results.gatherDisplacement(state.u);
        return last.ok;
      },
      progress_ && !quiet, [&] { return sectionResponses(state.u, time); });
  last.uzawa.solves += counted.solves;
  last.uzawa.newtonIterations += counted.newtonIterations;
  last.uzawa.linearIterations += counted.linearIterations;
  last.uzawa.contactUpdates += counted.contactUpdates;
  takeCoupling(coupled, last);
  return last;
}

std::vector<std::vector<double>> StepSolver::sectionResponses(const assembly::Vector &u, double time) const {
  const std::size_t sections = parts_.airflow->numSections();
  const auto load = assembly::followerPressureContribution(scene_.pressures.at(static_cast<std::size_t>(scene_.airflowLoad)));
  assembly::MultiVector rhs(u.getMap(), sections), x(u.getMap(), sections);
  // K du = -df/dp, and the load's residual is -f_ext: du = K^{-1} f_ext of the section's 1 Pa.
  parts_.airflow->forEachUnitSectionPressure([&](std::size_t i) {
    rhs.getVectorNonConst(i)->update(-1.0, parts_.assembler.loadResidual(u, time, load.get()), 0.0);
  });
  // The factors the step's last Newton solve left (no assembly, no factorisation), else afresh.
  try {
    parts_.newton.solveWithLastTangent(rhs, x, kResponseTolerance);
  } catch (const std::runtime_error &) {
    parts_.newton.solveTangent(u, rhs, x, kResponseTolerance);
  }
  const assembly::ResultEvaluator results(parts_.assembler);
  std::vector<std::vector<double>> responses(sections);
  for (std::size_t i = 0; i < sections; ++i) responses[i] = results.gatherDisplacement(*x.getVector(i));
  return responses;
}

StepAttempt StepSolver::solveSolid(double time, double dt, StepState &state, bool quiet,
                                   const std::vector<double> &inputs, double loadScale,
                                   const UzawaLoop::OuterCondition &outer) const {
  StepAttempt out;
  if (keptScope_ == ReuseScope::step) parts_.newton.forgetLinearSolver();
  MumpsPreconditionerFactory::beginStep(); // fresh factors for each step, retry and candidate
  parts_.assembler.applyDirichlet(state.u, time);
  parts_.model.beginStep(time, dt, inputs); // trial activation; lambda_c stays at its committed value
  parts_.model.setMultipliers(state.lambda);

  // The Newton tolerance scales with the load: the external force and the step's initial
  // residual, which the first Newton solve assembles anyway (or the caller's load scale, when it
  // starts near the solution).
  const double leastScale = std::max(parts_.assembler.externalForceNorm(time), loadScale);
  const double relative = parts_.newton.relativeResidualTolerance();
  const NewtonSolver::ToleranceRule tolerance = [leastScale, relative, &out](double initialResidualNorm) {
    double reference = std::max(leastScale, initialResidualNorm);
    if (!(reference > 0.0)) reference = 1.0;
    out.loadScale = reference;
    return relative * reference;
  };

  const bool progress = progress_ && !quiet;
  auto onNewton = [&](int k, double normF, int krylov) {
    if (progress) std::printf("    newton %2d  |f| = %.3e  krylov %d\n", k, normF, krylov);
  };
  auto onUzawa = [&](int k, const NewtonResult &n, const DilatationError &e,
                     const std::vector<contact::ContactMeasures> &contacts) {
    if (!progress) return;
    std::printf("  uzawa %d: newton %d  krylov %d  dilatation error max %.2e  mean %.2e  max|theta-1| %.2e", k,
                n.iterations, n.linearIterations, e.max, e.mean, e.maxVolumeChange);
    // The gap error beside the dilatation error: the loop ends when both are within tolerance.
    for (std::size_t c = 0; c < contacts.size(); ++c)
      if (contacts[c].augmented)
        std::printf("  %s gap error %.2e (%ld points)", scene_.contacts[c].name.c_str(), contacts[c].largestGapError,
                    contacts[c].activePoints);
    std::printf("\n");
  };
  const std::vector<double> ratios = parts_.uzawa.penaltyRatios();
  out.uzawa = parts_.uzawa.solve(state.u, state.lambda, tolerance, onNewton, onUzawa, outer);
  for (std::size_t t = 0; talk_ && t < ratios.size(); ++t)
    if (parts_.uzawa.penaltyRatios()[t] != ratios[t])
      std::printf("  note: the Uzawa loop contracts slowly in tissue '%s': kappa_AL raised to %.3g mu for the rest of "
                  "the run\n", scene_.tissues[t].name.c_str(), parts_.uzawa.penaltyRatios()[t]);
  // The history at the converged state: lambda_c of every point with this step's activation.
  if (out.uzawa.converged) out.muscle = assembly::updateMuscleHistory(assembly::ResultEvaluator(parts_.assembler), state.u, parts_.history);
  out.ok = out.uzawa.converged && out.muscle.valid;
  if (out.ok) measureCorners(state, time, out);
  if (out.ok) refuseInsideOut(state, out);
  if (!out.ok && out.why.empty()) out.why = failureReason(out);
  return out;
}

// What the Gauss points cannot see: the smallest det F at the elements' corners, at all corners
// and at regular ones, reported per step; and how much of an element is turned over, which
// refuses the state beyond fem::kFoldedFraction. A corner det F alone cannot decide: in the sound
// tongue scenes corners of near-degenerate imaged elements turn over to det F = -8.5 (s8_4_sg)
// and even regular ones, whose reference det is at least 0.2 of their element's mean, to -1.1
// (s8_5 passive supine), while a regular cube folded by a node pushed to its centre has -0.5; the
// turned-over volume of those corners stays below 0.14 % of their elements, the fold's is 0.31 %
// (doc/theory.md, "Folded elements").
void StepSolver::measureCorners(const StepState &state, double time, StepAttempt &attempt) const {
  const auto worst = assembly::ResultEvaluator(parts_.assembler).worstCorner(state.u);
  attempt.minCornerJ = worst.J;
  attempt.cornerElement = worst.element;
  attempt.minRegularCornerJ = worst.regularJ;
  attempt.regularCornerElement = worst.regularElement;
  attempt.turnedOver = worst.turnedOver;
  if (!(worst.turnedOver > fem::kFoldedFraction)) return;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto n : scene_.mesh.elements[worst.turnedOverElement]) centroid += scene_.mesh.nodes[n] / 8.0;
  char why[600];
  std::snprintf(why, sizeof why,
                "element %lld (reference centroid %.4g, %.4g, %.4g m; numbered from 0) is folded through itself in the converged state "
                "at t = %.6g: %.3g %% of its volume is turned inside out (its smallest corner det F %.3g), beyond the "
                "%.2g %% a sound state keeps; the mesh is too coarse or too distorted there for this deformation: "
                "refine it there, or lower the load",
                static_cast<long long>(worst.turnedOverElement), centroid.x(), centroid.y(), centroid.z(), time,
                100.0 * worst.turnedOver, worst.turnedOverCornerJ, 100.0 * fem::kFoldedFraction);
  attempt.ok = false;
  attempt.why = why;
  attempt.folded = {{"time", time},
                    {"element", worst.turnedOverElement},
                    {"reference_centroid", {centroid.x(), centroid.y(), centroid.z()}},
                    {"turned_over_volume", worst.turnedOver},
                    {"min_corner_J", worst.turnedOverCornerJ},
                    {"threshold", fem::kFoldedFraction}};
}

void StepSolver::refuseInsideOut(const StepState &state, StepAttempt &attempt) const {
  if (planes_.empty()) return;
  const model::PlaneCrossing deepest =
      model::deepestCrossing(planes_, scene_.mesh, assembly::ResultEvaluator(parts_.assembler).gatherDisplacement(state.u));
  // Material across a symmetry plane overlaps its mirror image. A node next to a plane but not
  // on it (on another plane's edge) may sit a little across in a sound state (2.6e-9 m, 1.3e-6 of
  // the thick sphere's size, at p = 0.72 mu): 1e-3 of the body's size is the threshold.
  if (!(deepest.distance < -1e-3 * lengthScale_)) return;
  const model::SymmetryPlane &plane = planes_[deepest.plane];
  const std::string &name = scene_.dirichlet[plane.condition].name;
  const char axis = "xyz"[plane.axis];
  char why[400];
  std::snprintf(why, sizeof why,
                "the converged state is inside out: the body has passed through its symmetry plane '%s' (%c = %.6g m), "
                "node %zu lying %.3g m on the far side, where its mirror image is",
                name.c_str(), axis, plane.position, static_cast<std::size_t>(deepest.node), -deepest.distance);
  attempt.ok = false; // on a softened path the monitor counts it as a failure past the maximum
  attempt.why = why;
  attempt.insideOut = {{"condition", name}, {"node", deepest.node}, {"distance", -deepest.distance}};
}

} // namespace glossa::solvers
