#include "solvers/parameters/ControlSection.hpp"

#include "io/deck/NameList.hpp"

#include <algorithm>
#include <sstream>

#include "io/deck/DeckError.hpp"
#include "io/deck/ParameterSpec.hpp"

namespace glossa::solvers {

using Teuchos::Array;
using Teuchos::ParameterList;

namespace {
std::vector<std::string> splitList(const std::string &s) { return io::splitNameList(s); }
} // namespace

ParameterList controlParameters() {
  ParameterList p;
  io::declareString(p, "type", "none",
                    "none, genetic algorithm or gradient: at every step choose the neural inputs of the "
                    "controlled muscle groups that keep the control points at their goals (eq. 25; "
                    "doc/control.md); gradient: projected Gauss-Newton on continuous inputs with "
                    "sensitivities from the converged tangent",
                    {"none", "genetic algorithm", "gradient"});
  io::declareString(p, "control points", "", "named points held at their reference positions, comma separated");
  io::declareDoubleArray(p, "weights", Array<double>(), "", "w_p per control point (empty: all 1)", 0,
                         io::Range::nonNegative());
  io::declareString(p, "muscle groups", "", "the groups the controller drives, comma separated (empty: all)");
  io::declareString(p, "always evaluated", "", "groups never pruned, comma separated (the genioglossus parts)");
  io::declareBool(p, "pruning", true, "search only the groups whose mean fibre stretch is above its reference");
  io::declareBool(p, "keep active groups", true,
                  "never prune a group whose input was above 0 at the previous step (a muscle that holds "
                  "the points is near its reference stretch, and pruning it would drop the hold)");
  io::declareDouble(p, "pruning tolerance", 0.0, "", "how far above the reference stretch counts as tension",
                    io::Range::nonNegative());
  io::declareString(p, "genes", "binary", "neural inputs in {0, 1} (the paper) or in [0, 1]", {"binary", "continuous"});
  io::declareInt(p, "population", 16, "genomes per generation", io::Range::closed(2, 100000));
  io::declareInt(p, "generations", 20, "generation limit per control step", io::Range::closed(1, 100000));
  io::declareInt(p, "elite", 2, "best genomes carried over unchanged", io::Range::closed(1, 100000));
  io::declareInt(p, "tournament size", 2, "genomes per selection tournament", io::Range::closed(1, 100000));
  io::declareDouble(p, "crossover rate", 0.9, "", "probability of uniform crossover", io::Range::closed(0, 1));
  io::declareDouble(p, "mutation rate", 0.1, "", "probability per gene", io::Range::closed(0, 1));
  io::declareDouble(p, "mutation sigma", 0.1, "", "continuous genes: Gaussian mutation width", io::Range::positive());
  io::declareInt(p, "stagnation generations", 5, "stop after this many generations without improvement",
                 io::Range::closed(1, 100000));
  io::declareString(p, "prediction seed", "none",
                    "genetic algorithm: a prediction that joins generation 0 after the previous best: none; "
                    "linear extrapolation, 2 u(k-1) - u(k-2) of the last two steps' inputs clipped to [0, 1]; "
                    "Gauss-Newton step, one bounded linearised step from the previous best (one solve and one "
                    "sensitivity more per step)",
                    {"none", "linear extrapolation", "Gauss-Newton step"});
  io::declareInt(p, "prediction seed steps", 1,
                 "Gauss-Newton step seed: k seeds at step lengths 1, 1/2, ..., 2^(1-k) of the linearised step "
                 "(a line search in generation 0, for a response the linearisation overshoots)",
                 io::Range::closed(1, 16));
  io::declareDouble(p, "effort weight", 0.0, "m",
                    "the price of activation: the GA ranks candidates by eq. 25 + w sum u^2, the gradient "
                    "controller minimises sum |r_p|^2 + w^2 sum u^2; among inputs that hold the points "
                    "equally well the least activation wins (0: eq. 25 alone)",
                    io::Range::nonNegative());
  io::declareDouble(p, "airway weight", 0.0, "1/m",
                    "the airway term w_A max(0, A_open - A) joins eq. 25 in the objective, A the smallest lumen "
                    "area of the candidate's state (the deck's Airway section); w_A makes it a length; the "
                    "gradient controller's residual gains its row (doc/control.md, 'The airway term'); 0: none",
                    io::Range::nonNegative());
  io::declareDouble(p, "airway open area", 0.0, "m^2",
                    "A_open of the airway term: a smallest lumen area at or above it costs nothing (required, "
                    "> 0, with an airway weight)",
                    io::Range::nonNegative());
  io::declareDouble(p, "objective tolerance", 0.0, "m", "stop once the objective (eq. 25) is below this",
                    io::Range::nonNegative());
  io::declareInt(p, "gradient iterations", 4, "gradient: Gauss-Newton iterations (sensitivity solves) per step",
                 io::Range::closed(1, 1000));
  io::declareInt(p, "gradient backtracks", 3, "gradient: step halvings when a step does not lower the objective",
                 io::Range::closed(0, 60));
  io::declareDouble(p, "gradient step tolerance", 1e-3, "", "gradient: stop when no input would move by more",
                    io::Range{0.0, 1.0, true, false});
  io::declareDouble(p, "gradient damping", 1e-6, "", "gradient: Levenberg damping relative to the largest diagonal of S^T S",
                    io::Range::nonNegative());
  io::declareBool(p, "verify sensitivities", false,
                  "gradient: also difference two full solves per input (step 1e-3) and report the largest "
                  "relative difference from the tangent's sensitivity (summary.json, sensitivity_check)");
  io::declareString(p, "sensitivity tangent", "auto",
                    "augmented Lagrangian: the tangent of the gradient controller's sensitivities and of the "
                    "responses the GA's candidates start along; constrained: the converged "
                    "Uzawa loop's (the physical bulk modulus capped at 'sensitivity penalty ratio' mu, the "
                    "multipliers following the pressures); inner: the Newton solves' own at fixed multipliers "
                    "(an error of order mu / kappa_AL; the GA's prediction seed always uses it); auto: constrained "
                    "where the sensitivities are solved directly (Linear solver/sensitivity solve), inner where "
                    "by a Krylov method (doc/control.md, 'The sensitivities')",
                    {"auto", "constrained", "inner"});
  io::declareDouble(p, "sensitivity penalty ratio", 1e3, "",
                    "the constrained sensitivity tangent's cap on the bulk modulus, in units of mu",
                    io::Range::closed(1.0, 1e8));
  io::declareBool(p, "predicted start", true,
                  "a candidate's solve starts from a solved state moved along its sensitivities to the new "
                  "inputs, with its multipliers, instead of from the step's start (retried from there if it "
                  "fails; doc/control.md, 'Where a candidate starts'): gradient, the accepted candidate's; "
                  "GA, the Gauss-Newton seed's solve (Control/prediction seed = Gauss-Newton step; without "
                  "it the GA's candidates start from the step's start)");
  io::declareBool(p, "retry turned-over starts", true,
                  "GA with predicted start: a candidate whose moved start turns an element over (there or on "
                  "Newton's way) is solved again from the step's start (true), or ranked as failed without that "
                  "solve (false: faster, a different search; doc/control.md, 'Where a candidate starts')");
  io::declareInt(p, "seed", 1, "random seed (same seed and rank count: the same run)", io::Range::closed(0, 2147483647));
  return p;
}

bool controlRequested(const ParameterList &controlSection) {
  return controlSection.get<std::string>("type") != "none";
}

ControlSetup buildControl(const io::Deck &deck, const model::Scene &scene) {
  const ParameterList &c = deck.root().sublist("Control");
  ControlSetup s;
  s.enabled = controlRequested(c);
  if (!s.enabled) return s;
  auto where = [&](const char *name) { return deck.where({"Control", name}); };
  const auto &groups = scene.muscles.groups;
  std::vector<std::string> groupNames;
  for (const auto &g : groups) groupNames.push_back(g.name);
  for (const auto &name : splitList(c.get<std::string>("control points"))) {
    const auto it = scene.mesh.namedPoints.find(name);
    if (it == scene.mesh.namedPoints.end())
      throw io::DeckError(where("control points") + ": no named point '" + name + "' (declare it in Named points)");
    if (it->second.probe())
      throw io::DeckError(where("control points") + ": '" + name + "' is a probe inside an element; a control "
                          "point must be a mesh node");
    s.pointNames.push_back(name);
    s.pointNodes.push_back(it->second.node);
  }
  if (s.pointNames.empty()) throw io::DeckError(where("control points") + " is empty: name the points to hold");
  s.goals.resize(3, static_cast<Eigen::Index>(s.pointNodes.size()));
  for (std::size_t p = 0; p < s.pointNodes.size(); ++p)
    s.goals.col(static_cast<Eigen::Index>(p)) = scene.mesh.imagedPosition(s.pointNodes[p]);
  const auto &w = c.get<Array<double>>("weights");
  if (!w.empty() && w.size() != static_cast<Array<double>::size_type>(s.pointNames.size()))
    throw io::DeckError(where("weights") + ": " + std::to_string(w.size()) + " weights for " +
                        std::to_string(s.pointNames.size()) + " control points");
  s.weights = Eigen::VectorXd::Ones(static_cast<Eigen::Index>(s.pointNames.size()));
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(w.size()); ++i) s.weights(i) = w[i];
  const auto listed = splitList(c.get<std::string>("muscle groups"));
  for (std::size_t g = 0; g < groups.size(); ++g)
    if (listed.empty() || std::find(listed.begin(), listed.end(), groups[g].name) != listed.end())
      s.groups.push_back(static_cast<int>(g));
  for (const auto &name : listed)
    if (std::find(groupNames.begin(), groupNames.end(), name) == groupNames.end())
      throw io::DeckError(where("muscle groups") + ": no muscle group '" + name + "'");
  if (s.groups.empty()) throw io::DeckError(where("muscle groups") + ": the scene has no muscle group to control");

  auto &p = s.parameters;
  p.pruning = c.get<bool>("pruning");
  p.pruningTolerance = c.get<double>("pruning tolerance");
  p.keepActiveGroups = c.get<bool>("keep active groups");
  p.alwaysEvaluated = splitList(c.get<std::string>("always evaluated"));
  p.type = c.get<std::string>("type") == "gradient" ? control::ControllerType::gradient
                                                    : control::ControllerType::geneticAlgorithm;
  p.verifySensitivities = c.get<bool>("verify sensitivities");
  p.predictedStart = c.get<bool>("predicted start");
  p.retryTurnedOverStarts = c.get<bool>("retry turned-over starts");
  p.sensitivityPenaltyRatio = c.get<double>("sensitivity penalty ratio");
  const std::string tangent = c.get<std::string>("sensitivity tangent");
  p.sensitivityTangent = tangent == "constrained" ? control::SensitivityTangent::constrained
                         : tangent == "inner"     ? control::SensitivityTangent::inner
                                                  : control::SensitivityTangent::automatic;
  const std::string prediction = c.get<std::string>("prediction seed");
  p.predictionSeed = prediction == "linear extrapolation" ? control::PredictionSeed::extrapolation
                     : prediction == "Gauss-Newton step"  ? control::PredictionSeed::gaussNewtonStep
                                                          : control::PredictionSeed::none;
  p.predictionSeedSteps = c.get<int>("prediction seed steps");
  p.effortWeight = c.get<double>("effort weight");
  p.airwayWeight = c.get<double>("airway weight");
  p.airwayOpenArea = c.get<double>("airway open area");
  if (p.airwayWeight > 0.0 && deck.root().sublist("Airway").get<std::string>("face set").empty())
    throw io::DeckError(deck.where({"Control", "airway weight"}) +
                        ": the airway term measures the lumen of the deck's Airway section, which has no face set; "
                        "give Airway/face set, wall file, start point and end point, or set the weight to 0");
  if (p.airwayWeight > 0.0 && !(p.airwayOpenArea > 0.0))
    throw io::DeckError(deck.where({"Control", "airway open area"}) +
                        " = 0 with an airway weight: give the area above which the lumen costs nothing (> 0, m^2)");
  p.gradient.maxIterations = c.get<int>("gradient iterations");
  p.gradient.maxBacktracks = c.get<int>("gradient backtracks");
  p.gradient.stepTolerance = c.get<double>("gradient step tolerance");
  p.gradient.damping = c.get<double>("gradient damping");
  p.gradient.objectiveTolerance = c.get<double>("objective tolerance");
  auto &ga = p.ga;
  ga.geneType = c.get<std::string>("genes") == "binary" ? control::GeneType::binary : control::GeneType::continuous;
  ga.populationSize = c.get<int>("population");
  ga.generations = c.get<int>("generations");
  ga.eliteCount = c.get<int>("elite");
  ga.tournamentSize = c.get<int>("tournament size");
  ga.crossoverRate = c.get<double>("crossover rate");
  ga.mutationRate = c.get<double>("mutation rate");
  ga.mutationSigma = c.get<double>("mutation sigma");
  ga.stagnationGenerations = c.get<int>("stagnation generations");
  ga.objectiveTolerance = c.get<double>("objective tolerance");
  ga.seed = static_cast<std::uint64_t>(c.get<int>("seed"));
  try {
    p.validate();
    p.alwaysEvaluatedMask(groupNames);
  } catch (const std::invalid_argument &e) {
    throw io::DeckError(deck.where({"Control"}) + ": " + e.what());
  }
  return s;
}

} // namespace glossa::solvers
