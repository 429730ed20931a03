#include "solvers/parameters/RunChecks.hpp"

#include "io/deck/Deck.hpp"
#include "io/deck/DeckError.hpp"
#include "model/Scene.hpp"
#include "solvers/incompressibility/Augmentation.hpp"
#include "solvers/parameters/ControlSection.hpp"

namespace glossa::solvers {

namespace {
// Incompressibility/method = mixed carries the element pressures in the Newton iterate: it needs
// the mixed element, a full Newton step (the pressure increment is not line-searched), an
// iterative block solve, and no controller (its sensitivities are condensed solves).
void requireMixedCompatible(const LinearSolverParameters &linear, bool controlled, const model::Scene &scene) {
  const std::string why = "Incompressibility/method = mixed needs ";
  if (scene.formulation != model::ElementFormulation::Q1P0) throw io::DeckError(why + "Material/element = Q1P0");
  if (linear.type == LinearSolverType::direct)
    throw io::DeckError(why + "Linear solver/type = iterative or auto (the block system is solved by GMRES; "
                              "auto may precondition its displacement block by a direct solve)");
  if (controlled)
    throw io::DeckError(why + "Control/type = none (the controllers' sensitivities use the condensed tangent)");
  if (scene.tissues.size() > 1)
    throw io::DeckError(why + "one tissue (its pressure state holds one volumetric law); use the augmented Lagrangian "
                              "for Material/Tissues");
}

// Time/path following = arc length makes the time an unknown of each step (ArcLengthContinuation):
// nothing else may depend on the time in a way the path cannot follow back.
// `parameter`: the Time parameter that asks for it ("path following", or "at a limit point" =
// follow, whose run may be restarted from a checkpoint written before the path began).
void requireArcLengthCompatible(const io::Deck &deck, const RunConfiguration &config, const model::Scene &scene,
                                bool restart, const std::string &parameter) {
  const std::string why = deck.where({"Time", parameter}) + ": arc-length continuation needs ";
  if (config.incompressibility.method != IncompressibilityMethod::penalty)
    throw io::DeckError(why + "Incompressibility/method = penalty (the augmented Lagrangian's multipliers and the "
                              "mixed method's pressures would change within a continuation step; a penalty with nu "
                              "= 0.49999 keeps the thick sphere's volume to 4e-5)");
  if (config.controlled) throw io::DeckError(why + "Control/type = none (a controller searches inputs at a given time)");
  if (!scene.muscles.groups.empty())
    throw io::DeckError(why + "no muscle groups (their activation is a history in time, which the path may run "
                              "backwards)");
  for (const auto &bc : scene.dirichlet) {
    bool moves = !bc.value.isZero();
    for (const auto &e : bc.expression) moves = moves || static_cast<bool>(e);
    if (moves)
      throw io::DeckError(why + "supports that prescribe no motion: Boundary conditions/" + bc.name +
                          " prescribes a displacement (drive the path by its loads)");
  }
  if (parameter == "path following" && restart)
    throw io::DeckError("--restart does not continue an arc-length path (its direction and step are LOCA's own "
                        "state); run it again");
}
} // namespace

void checkControlGroupCount(int controlGroups, int ranks) {
  if (controlGroups < 1 || ranks % controlGroups != 0)
    throw io::DeckError("--control-groups " + std::to_string(controlGroups) +
                        " must be at least 1 and divide the number of ranks (" + std::to_string(ranks) + ")");
}

void checkRunConfiguration(const io::Deck &deck, const RunConfiguration &config, const model::Scene &scene,
                           const ControlSetup &control, const RunCheckContext &context) {
  checkControlGroupCount(context.controlGroups, context.ranks);
  // Each tissue's law against the method (a penalty cannot hold nu = 0.5).
  for (const auto &tissue : scene.tissues)
    Augmentation::tangentKappa(config.incompressibility, tissue.volumetric.kappa(), tissue.matrix->shearModulus());
  if (config.incompressibility.method == IncompressibilityMethod::mixed)
    requireMixedCompatible(config.linear, config.controlled, scene);
  const bool onPath = config.time.pathFollowing == PathFollowing::arcLength;
  if (config.time.dynamics.dynamic()) {
    // Inertia enters the condensed displacement system's residual and tangent; the mixed block
    // system and a load path parametrised by the time have no place for it.
    if (config.incompressibility.method == IncompressibilityMethod::mixed)
      throw io::DeckError(deck.where({"Time", "analysis"}) + " = dynamic needs the displacement formulation: " +
                          deck.where({"Incompressibility", "method"}) + " is mixed; allowed with dynamic: penalty or "
                          "augmented Lagrangian");
    if (onPath || config.time.atLimitPoint == AtLimitPoint::follow)
      throw io::DeckError(deck.where({"Time", "analysis"}) + " = dynamic steps in time: " +
                          deck.where({"Time", onPath ? "path following" : "at a limit point"}) +
                          " asks for arc-length continuation; allowed with dynamic: path following = load control, "
                          "at a limit point = stop or ignore");
  }
  // The arc-length path is LOCA's own solve, which the flow's coupling does not reach.
  if (scene.airflowLoad >= 0 && (onPath || config.time.atLimitPoint == AtLimitPoint::follow))
    throw io::DeckError(deck.where({"Airflow", "driven by"}) + ": the airflow is coupled to load steps; " +
                        deck.where({"Time", onPath ? "path following" : "at a limit point"}) +
                        " asks for arc-length continuation; allowed with airflow: path following = load control, "
                        "at a limit point = stop or ignore");
  if (onPath || config.time.atLimitPoint == AtLimitPoint::follow)
    requireArcLengthCompatible(deck, config, scene, context.restart, onPath ? "path following" : "at a limit point");
  for (const auto &[key, sets] : {std::make_pair("resultant face sets", &config.output.resultantFaceSets),
                                  std::make_pair("volume face sets", &config.output.volumeFaceSets)})
    for (const auto &name : *sets)
      if (!scene.mesh.faceSets.count(name))
        throw io::DeckError(deck.where({"Output", key}) + ": no face set '" + name + "'");
  if (context.controlGroups > 1 &&
      !(control.enabled && control.parameters.type == control::ControllerType::geneticAlgorithm))
    throw io::DeckError("--control-groups " + std::to_string(context.controlGroups) +
                        " needs Control/type = genetic algorithm (the candidates it shares out)");
}

std::vector<std::string> ignoredIterativeSettings(const RunConfiguration &config, bool direct, long long unknowns) {
  std::vector<std::string> warnings;
  if (config.linear.type != LinearSolverType::automatic || !direct) return warnings;
  for (const std::string &where : config.givenIterativeOnly)
    warnings.push_back(where + " is not used: Linear solver/type = auto solves " + std::to_string(unknowns) +
                       " unknowns directly (doc/incompressibility.md, \"Choosing direct or iterative\"); set type = iterative to use it");
  return warnings;
}

} // namespace glossa::solvers
