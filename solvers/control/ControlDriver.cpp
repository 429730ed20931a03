#include "solvers/control/ControlDriver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include "control/BoundedLeastSquares.hpp"
#include "control/ElitistGeneticAlgorithm.hpp"
#include "control/GaussNewtonController.hpp"
#include "control/InputPrediction.hpp"
#include "control/MusclePruning.hpp"

namespace glossa::solvers {

namespace {
// --verbose: a line per candidate solve, its value or why it failed, what it cost and whether it
// was solved twice (doc/output.md). Candidates count from 1 within the step; the GA's seed solves
// (made before its generations) say so instead.
std::string candidateLine(long index, const CandidateSolve &solve, double objective, bool airwayTerm,
                          double seconds) {
  char head[64];
  if (index < 0)
    std::snprintf(head, sizeof head, "    seed solve");
  else
    std::snprintf(head, sizeof head, "    candidate %ld", index + 1);
  char cost[96];
  std::snprintf(cost, sizeof cost, "newton %d, uzawa %d, %.2f s%s", solve.statistics.newtonIterations,
                solve.statistics.solves, seconds,
                solve.solvedAgain ? ", solved again from the step's start" : "");
  char value[64];
  std::snprintf(value, sizeof value, "%s %.4g mm", airwayTerm ? "eq. 25 + airway term" : "eq. 25",
                1e3 * objective);
  return std::string(head) + ": " +
         (solve.ok ? std::string(value) + ", " + cost : "failed, " + std::string(cost) + ": " + solve.why);
}
}  // namespace

// Every candidate is a full step solve from the committed state. The first candidate to beat
// every earlier one by its rank (the GA: eq. 25; the gradient controller: the sum of squares it
// minimises) has its state kept, so the winner's state is at hand when the search ends.
struct ControlDriver::Search {
  ControlStepResult result;
  double rank = std::numeric_limits<double>::infinity();
  long index = -1; // the winner's position in the order of evaluation (ties among control groups)
  std::size_t predictionSolves = 0; // full solves made for the GA's seeds, outside the GA
  // The Gauss-Newton seed's own solve, at the previous best inputs, made by every control group:
  // generation 0 holds those inputs again, and takes their value from here instead of a solve.
  std::vector<double> solvedInputs;
  double solvedValue = std::numeric_limits<double>::infinity(); // eq. 25 + effort; inf: failed
  std::size_t reused = 0; // genomes valued from solvedInputs (counted alike in every group)
  std::size_t failed = 0, failedPredictions = 0; // this group's failed solves; of them, seed solves
  std::size_t screened = 0, screenedPredictions = 0; // of the failed, screened (CandidateSolve::screened)
  // This group's candidates solved twice (CandidateSolve::solvedAgain). The GA's seed solve is never
  // one: it is the step's first, before any moved start exists, so every count here is the group's own.
  std::size_t solvedAgain = 0;
  double keptArea = std::numeric_limits<double>::quiet_NaN(); // the kept candidate's smallest lumen area
};

ControlDriver::ControlDriver(ControlDriverSetup setup, ControlPlant &plant, const ControlGroups &groups)
    : setup_(std::move(setup)), plant_(plant), groups_(groups), objective_(setup_.goals, setup_.weights) {}

Eigen::Matrix3Xd ControlDriver::positions(const Eigen::Matrix3Xd &pointDisplacement) const {
  return setup_.referencePositions + pointDisplacement;
}

std::vector<int> ControlDriver::evaluatedGroups(const std::vector<double> &committedStretch) const {
  const auto &p = setup_.parameters;
  const auto &controlled = setup_.controlled;
  // Pruning against the stretch in the reference configuration, 1 (F = I there; with a
  // zero-strain configuration as the reference this is §6.1's value on X0).
  std::vector<double> stretch, reference;
  std::vector<bool> always;
  const auto alwaysMask = p.alwaysEvaluatedMask(setup_.groupNames);
  for (std::size_t i = 0; i < controlled.size(); ++i) {
    const int g = controlled[i];
    stretch.push_back(committedStretch[g]);
    reference.push_back(1.0);
    const bool active = p.keepActiveGroups && i < previousBest_.size() && previousBest_[i] > 0.0;
    always.push_back(alwaysMask[g] || active);
  }
  std::vector<int> local = p.pruning ? control::groupsInTension(stretch, reference, p.pruningTolerance, always)
                                     : std::vector<int>();
  if (!p.pruning)
    for (std::size_t i = 0; i < controlled.size(); ++i) local.push_back(static_cast<int>(i));
  std::vector<int> evaluated;
  for (int i : local) evaluated.push_back(controlled[i]);
  return evaluated;
}

std::vector<double> ControlDriver::allInputs(const std::vector<int> &evaluated, const Eigen::VectorXd &v) const {
  std::vector<double> inputs(setup_.groupNames.size(), 0.0);
  for (std::size_t i = 0; i < evaluated.size(); ++i) inputs[evaluated[i]] = v(static_cast<Eigen::Index>(i));
  return inputs;
}

control::ControlEvaluation ControlDriver::solveCandidate(Search &search, const std::vector<double> &inputs,
                                                         bool rankByObjective, long index) {
  const auto started = std::chrono::steady_clock::now();
  const CandidateSolve solve = plant_.solve(inputs);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (solve.solvedAgain) ++search.solvedAgain;
  if (!solve.ok) {
    ++search.failed;
    if (index < 0) ++search.failedPredictions;
    if (solve.screened) ++(index < 0 ? search.screenedPredictions : search.screened);
    if (search.result.firstFailure.empty()) search.result.firstFailure = solve.why.empty() ? "no reason given" : solve.why;
  }
  control::ControlEvaluation e;
  e.objective = std::numeric_limits<double>::infinity();
  Eigen::VectorXd errors;
  if (solve.ok) {
    const Eigen::Matrix3Xd x = positions(solve.pointDisplacement);
    const auto v = objective_.evaluate(x);
    const double airway = airwayTerm(solve.smallestArea);
    e.ok = true;
    e.objective = v.total + airway;
    const Eigen::Matrix3Xd offset = x - setup_.goals;
    const auto &evaluated = search.result.evaluated;
    const double epsilon = rankByObjective ? 0.0 : setup_.parameters.effortWeight;
    const auto points = static_cast<Eigen::Index>(offset.size());
    const Eigen::Index airwayRows = hasAirwayTerm() ? 1 : 0;
    // The gradient controller's residual: the weighted offsets, the airway term's row, then
    // epsilon u per evaluated group.
    e.residual.resize(points + airwayRows + (epsilon > 0.0 ? static_cast<Eigen::Index>(evaluated.size()) : 0));
    e.residual.head(points) = Eigen::Map<const Eigen::VectorXd>(offset.data(), points);
    for (Eigen::Index p = 0; p < x.cols(); ++p) e.residual.segment<3>(3 * p) *= setup_.weights(p);
    if (airwayRows > 0) e.residual(points) = airway;
    if (epsilon > 0.0)
      for (std::size_t i = 0; i < evaluated.size(); ++i)
        e.residual(points + airwayRows + static_cast<Eigen::Index>(i)) = epsilon * inputs[evaluated[i]];
    errors = v.distance;
  }
  const double rank = !e.ok              ? e.objective
                      : rankByObjective ? e.objective + effort(inputs)
                                        : e.residual.squaredNorm();
  if (rank < search.rank) {
    search.rank = rank;
    search.index = index;
    search.result.objective = e.objective;
    search.result.inputs = inputs;
    search.result.pointErrors = errors;
    search.result.solve = solve.statistics;
    search.result.couplingIterations = solve.couplingIterations;
    search.result.couplingChange = solve.couplingChange;
    search.keptArea = solve.smallestArea;
    plant_.keepLast();
  }
  if (setup_.talk)
    std::printf("%s\n", candidateLine(index, solve, e.objective, hasAirwayTerm(), seconds).c_str());
  return e;
}

ControlStepResult ControlDriver::step(int committedSteps, const std::vector<double> &committedStretch) {
  Search search;
  search.result.objective = std::numeric_limits<double>::infinity();
  search.result.evaluated = evaluatedGroups(committedStretch);
  std::vector<double> previousInputs(setup_.groupNames.size(), 0.0);
  for (std::size_t i = 0; i < setup_.controlled.size() && i < previousBest_.size(); ++i)
    previousInputs[setup_.controlled[i]] = previousBest_[i];

  if (setup_.parameters.type == control::ControllerType::geneticAlgorithm)
    searchGenetic(search, committedSteps, previousInputs);
  else
    searchGradient(search, previousInputs);

  ControlStepResult &result = search.result;
  if (!result.found()) return result;
  olderBest_ = previousBest_;
  previousBest_.assign(setup_.controlled.size(), 0.0);
  for (std::size_t i = 0; i < setup_.controlled.size(); ++i) previousBest_[i] = result.inputs[setup_.controlled[i]];
  return result;
}

void ControlDriver::searchGenetic(Search &search, int committedSteps, const std::vector<double> &previousInputs) {
  const std::vector<int> &evaluated = search.result.evaluated;
  const auto groupCount = static_cast<std::size_t>(groups_.count());
  long evaluatedSoFar = 0;
  std::size_t failedInGenerations = 0; // over all groups: every rank sees every value
  auto evaluate = [&](const std::vector<control::Genome> &genomes) {
    // With several control groups each group takes the batch's next unsolved candidate when it is
    // done with one (claim), so a group that drew quick solves (or failures) is not left waiting
    // for the other; every rank then sees every objective, each taken from the group that solved
    // it. A candidate's solve starts from the step's own state whichever group solves it, so the
    // objectives do not depend on who took what (regression.*_ga_control_groups).
    std::vector<double> values(genomes.size(), 0.0);
    std::vector<bool> known(genomes.size(), false);
    std::vector<std::vector<double>> inputs(genomes.size());
    for (std::size_t i = 0; i < genomes.size(); ++i) {
      inputs[i] = control::inputsFromGenome(evaluated, genomes[i], setup_.groupNames.size());
      known[i] = !search.solvedInputs.empty() && inputs[i] == search.solvedInputs;
      if (known[i]) ++search.reused;
    }
    const auto solve = [&](std::size_t i) {
      values[i] = known[i] ? search.solvedValue
                           : solveCandidate(search, inputs[i], true, evaluatedSoFar + static_cast<long>(i)).objective +
                                 effort(inputs[i]); // +inf stays +inf for a failed solve
    };
    // One group claims them all, in order.
    for (long i = groups_.claim(genomes.size()); i >= 0; i = groups_.claim(genomes.size()))
      solve(static_cast<std::size_t>(i));
    evaluatedSoFar += static_cast<long>(genomes.size());
    if (groupCount > 1) values = groups_.sumOfGroupRoots(values);
    for (std::size_t i = 0; i < genomes.size(); ++i)
      if (!known[i] && !std::isfinite(values[i])) ++failedInGenerations;
    return values;
  };
  control::GeneticAlgorithmParameters gaParameters = setup_.parameters.ga;
  gaParameters.seed += static_cast<std::uint64_t>(committedSteps);
  const control::ElitistGeneticAlgorithm ga(gaParameters);
  const auto gaResult = ga.minimise(evaluated.size(), evaluate, geneticSeeds(search, previousInputs));
  // The GA runs on every rank alike: its counts are the same in every group.
  search.result.candidates = gaResult.evaluations - search.reused + search.predictionSolves;
  search.result.generations = gaResult.generations;
  search.result.failedCandidates = failedInGenerations + search.failedPredictions;
  // The seeds' solves are every group's alike; the generations' each group's own, summed.
  std::vector<double> ownCounts{static_cast<double>(search.screened),
                                static_cast<double>(search.solvedAgain)};
  if (groupCount > 1) ownCounts = groups_.sumOfGroupRoots(ownCounts);
  search.result.screenedCandidates = search.screenedPredictions + static_cast<std::size_t>(ownCounts[0]);
  search.result.solvedAgainCandidates = static_cast<std::size_t>(ownCounts[1]);
  search.result.stop = control::toString(gaResult.stopReason);
  if (groupCount > 1) shareWinner(search);
}

double ControlDriver::effort(const std::vector<double> &inputs) const {
  double sum = 0.0;
  for (double u : inputs) sum += u * u;
  return setup_.parameters.effortWeight * sum;
}

std::vector<control::Genome> ControlDriver::geneticSeeds(Search &search, const std::vector<double> &previousInputs) {
  const auto &p = setup_.parameters;
  const std::vector<int> &evaluated = search.result.evaluated;
  std::vector<control::Genome> seeds;
  if (p.seedWithPreviousBest && !previousBest_.empty()) seeds.push_back(control::genomeFromInputs(evaluated, previousInputs));
  if (p.predictionSeed == control::PredictionSeed::extrapolation && !olderBest_.empty()) {
    const auto prediction = control::linearPrediction(previousBest_, olderBest_, p.ga.geneType);
    std::vector<double> predicted(setup_.groupNames.size(), 0.0);
    for (std::size_t i = 0; i < setup_.controlled.size(); ++i) predicted[setup_.controlled[i]] = prediction[i];
    seeds.push_back(control::genomeFromInputs(evaluated, predicted));
  }
  if (p.predictionSeed == control::PredictionSeed::gaussNewtonStep && !evaluated.empty()) {
    for (const auto &predicted : gaussNewtonPrediction(search, previousInputs)) {
      control::Genome g = control::genomeFromInputs(evaluated, predicted);
      if (p.ga.geneType == control::GeneType::binary)
        for (double &u : g) u = u < 0.5 ? 0.0 : 1.0;
      if (std::find(seeds.begin(), seeds.end(), g) == seeds.end()) seeds.push_back(std::move(g));
    }
  }
  return seeds;
}

std::vector<std::vector<double>> ControlDriver::gaussNewtonPrediction(Search &search,
                                                                      const std::vector<double> &from) {
  // Ranked like the GA's candidates and solved ahead of them (index -1): every control group
  // solves it alike, so it is also the group-0 winner among equals.
  const control::ControlEvaluation e = solveCandidate(search, from, true, -1);
  ++search.predictionSolves;
  search.solvedInputs = from;
  search.solvedValue = e.objective + effort(from); // +inf for a failed solve
  if (!e.ok || search.result.inputs != from) return {from}; // no state to linearise about
  const std::vector<int> &evaluated = search.result.evaluated;
  const auto n = static_cast<Eigen::Index>(evaluated.size());
  const double epsilon = setup_.parameters.effortWeight;
  Eigen::VectorXd u(n);
  for (Eigen::Index i = 0; i < n; ++i) u(i) = from[evaluated[static_cast<std::size_t>(i)]];
  // The gradient controller's residual and its sensitivity (effort rows epsilon u included).
  Eigen::VectorXd r(e.residual.size() + (epsilon > 0.0 ? n : 0));
  r.head(e.residual.size()) = e.residual;
  if (epsilon > 0.0) r.tail(n) = epsilon * u;
  const Eigen::MatrixXd S = weightedSensitivity(search);
  ++search.result.sensitivities;
  if (S.size() == 0) return {from}; // no sensitivity: the previous best alone
  const double rho = setup_.parameters.gradient.damping * (S.transpose() * S).diagonal().maxCoeff() +
                     std::numeric_limits<double>::min();
  const Eigen::VectorXd du = control::solveBoundedLeastSquares(S, -r, -u, Eigen::VectorXd::Ones(n) - u, rho).x;
  // u + du lies in [0, 1]^n, and so does every point between it and u.
  std::vector<std::vector<double>> predictions;
  double t = 1.0;
  for (int k = 0; k < setup_.parameters.predictionSeedSteps; ++k, t *= 0.5) {
    std::vector<double> predicted = from;
    for (Eigen::Index i = 0; i < n; ++i)
      predicted[evaluated[static_cast<std::size_t>(i)]] = std::clamp(u(i) + t * du(i), 0.0, 1.0);
    predictions.push_back(std::move(predicted));
  }
  return predictions;
}

void ControlDriver::shareWinner(Search &search) {
  // The world's winner is the group best with the least rank, the earliest evaluated among
  // equals (the one-group rule); its root broadcasts the result and its kept state.
  const int count = groups_.count();
  std::vector<double> ranks(static_cast<std::size_t>(count), 0.0), indices(ranks);
  ranks[groups_.mine()] = search.rank;
  indices[groups_.mine()] = static_cast<double>(search.index);
  ranks = groups_.sumOfGroupRoots(ranks);
  indices = groups_.sumOfGroupRoots(indices);
  int winner = 0;
  for (int c = 1; c < count; ++c)
    if (ranks[c] < ranks[winner] || (ranks[c] == ranks[winner] && indices[c] < indices[winner])) winner = c;
  if (!std::isfinite(ranks[winner])) { // no candidate converged anywhere
    search.result.objective = search.rank = std::numeric_limits<double>::infinity();
    return;
  }
  std::vector<double> buffer;
  if (groups_.mine() == winner) {
    appendControlStepResult(search.result, buffer);
    const std::vector<double> state = plant_.packKept();
    buffer.insert(buffer.end(), state.begin(), state.end());
  }
  groups_.broadcastFromGroup(winner, buffer);
  std::size_t position = 0;
  search.result = readControlStepResult(buffer, position);
  search.rank = ranks[winner];
  search.index = static_cast<long>(indices[winner]);
  plant_.unpackKept(std::vector<double>(buffer.begin() + static_cast<long>(position), buffer.end()));
}

void ControlDriver::searchGradient(Search &search, const std::vector<double> &previousInputs) {
  // Projected Gauss-Newton from the previous step's inputs, on the evaluated groups.
  const std::vector<int> &evaluated = search.result.evaluated;
  long evaluatedSoFar = 0;
  auto evaluate = [&](const Eigen::VectorXd &v) {
    return solveCandidate(search, allInputs(evaluated, v), false, evaluatedSoFar++);
  };
  auto sensitivity = [&](const Eigen::VectorXd &v) {
    if (allInputs(evaluated, v) != search.result.inputs)
      throw std::logic_error("gradient controller: sensitivity asked away from the accepted state");
    return weightedSensitivity(search);
  };
  Eigen::VectorXd start(static_cast<Eigen::Index>(evaluated.size()));
  for (std::size_t i = 0; i < evaluated.size(); ++i) start(static_cast<Eigen::Index>(i)) = previousInputs[evaluated[i]];
  const control::GaussNewtonController controller(setup_.parameters.gradient);
  const auto gn = controller.minimise(start, evaluate, sensitivity);
  search.result.candidates = static_cast<std::size_t>(gn.evaluations);
  search.result.failedCandidates = search.failed;
  search.result.solvedAgainCandidates = search.solvedAgain;
  search.result.iterations = gn.iterations;
  search.result.sensitivities = gn.sensitivities;
  search.result.stop = control::toString(gn.stop);
}

Eigen::MatrixXd ControlDriver::weightedSensitivity(Search &search) {
  ControlStepResult &result = search.result;
  const InputSensitivity s = plant_.sensitivity(result.inputs, result.evaluated);
  if (!s.failure.empty()) {
    if (setup_.talk) std::printf("  sensitivity failed (%s): the search stops at the inputs it has\n", s.failure.c_str());
    return {};
  }
  result.sensitivityKrylov += s.krylovIterations;
  if (setup_.parameters.verifySensitivities) {
    result.sensitivityCheck = std::max(result.sensitivityCheck, differenceCheck(s, search));
    if (setup_.talk) std::printf("  sensitivity check: max |S - S_fd| / max |S_fd| = %.3e\n", result.sensitivityCheck);
  }
  const double epsilon = setup_.parameters.effortWeight;
  const auto n = static_cast<Eigen::Index>(result.evaluated.size());
  const Eigen::Index airwayRows = hasAirwayTerm() ? 1 : 0;
  Eigen::MatrixXd S(s.dxdu.rows() + airwayRows + (epsilon > 0.0 ? n : 0), s.dxdu.cols());
  S.topRows(s.dxdu.rows()) = s.dxdu;
  for (Eigen::Index p = 0; p < setup_.weights.size(); ++p) S.middleRows<3>(3 * p) *= setup_.weights(p);
  // The airway row, w_A max(0, A_open - A): -w_A dA/du where the term is active, 0 where the
  // kept state's lumen is open beyond A_open (the hinge's flat side).
  if (airwayRows > 0) {
    S.row(s.dxdu.rows()).setZero();
    if (airwayTerm(search.keptArea) > 0.0 && s.dAdu.size() == n)
      S.row(s.dxdu.rows()) = -setup_.parameters.airwayWeight * s.dAdu;
  }
  // d(epsilon u)/du of the effort rows of the residual (solveCandidate).
  if (epsilon > 0.0) S.bottomRows(n) = epsilon * Eigen::MatrixXd::Identity(n, n);
  return S;
}

bool ControlDriver::hasAirwayTerm() const { return setup_.parameters.airwayWeight > 0.0; }

double ControlDriver::airwayTerm(double smallestArea) const {
  if (!hasAirwayTerm() || !std::isfinite(smallestArea)) return 0.0;
  return setup_.parameters.airwayWeight * std::max(0.0, setup_.parameters.airwayOpenArea - smallestArea);
}

double ControlDriver::differenceCheck(const InputSensitivity &s, const Search &search) {
  // Central differences of full step solves (second-order one-sided at the bounds of [0, 1]): of
  // the control points and, with the airway term, of the smallest lumen area.
  constexpr double h = 1e-3;
  const std::vector<double> &accepted = search.result.inputs;
  const bool area = hasAirwayTerm() && s.dAdu.size() == s.dxdu.cols();
  auto solvedAt = [&](const std::vector<double> &inputs) {
    const CandidateSolve solve = plant_.solve(inputs);
    if (!solve.ok) throw std::runtime_error("verify sensitivities: a differenced solve failed: " + solve.why);
    Eigen::VectorXd v(solve.pointDisplacement.size() + (area ? 1 : 0));
    v.head(solve.pointDisplacement.size()) =
        Eigen::Map<const Eigen::VectorXd>(solve.pointDisplacement.data(), solve.pointDisplacement.size());
    if (area) v(v.size() - 1) = solve.smallestArea;
    return v;
  };
  Eigen::MatrixXd fd(s.dxdu.rows() + (area ? 1 : 0), s.dxdu.cols());
  for (std::size_t j = 0; j < search.result.evaluated.size(); ++j) {
    const int g = search.result.evaluated[j];
    auto at = [&](double du) {
      std::vector<double> inputs = accepted;
      inputs[g] += du;
      return solvedAt(inputs);
    };
    const double ug = accepted[g];
    const auto col = static_cast<Eigen::Index>(j);
    if (ug - h >= 0.0 && ug + h <= 1.0) fd.col(col) = (at(h) - at(-h)) / (2.0 * h);
    else {
      const double step = ug - h < 0.0 ? h : -h; // second-order one-sided, inside [0, 1]
      fd.col(col) = (-3.0 * at(0.0) + 4.0 * at(step) - at(2.0 * step)) / (2.0 * step);
    }
  }
  // Each block against its own scale: the points in metres, the area in square metres.
  auto relative = [](const Eigen::MatrixXd &analytic, const Eigen::MatrixXd &differenced) {
    const double scale = differenced.cwiseAbs().maxCoeff();
    return scale > 0.0 ? (analytic - differenced).cwiseAbs().maxCoeff() / scale : -1.0;
  };
  double check = relative(s.dxdu, fd.topRows(s.dxdu.rows()));
  if (area) {
    const double areaCheck = relative(s.dAdu, fd.bottomRows(1));
    if (setup_.talk) std::printf("  sensitivity check of the smallest area: %.3e\n", areaCheck);
    check = std::max(check, areaCheck);
  }
  return check;
}

} // namespace glossa::solvers
