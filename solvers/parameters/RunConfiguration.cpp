#include "solvers/parameters/RunConfiguration.hpp"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <sstream>

#include "input/AirflowParameters.hpp"
#include "io/deck/Deck.hpp"
#include "io/deck/DeckError.hpp"
#include "solvers/parameters/ControlSection.hpp"

namespace glossa::solvers {

namespace {
void listParameters(const Teuchos::ParameterList &list, const std::string &path, std::ostringstream &out) {
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string name = path + list.name(it);
    const Teuchos::ParameterEntry &entry = list.entry(it);
    if (entry.isList()) listParameters(Teuchos::getValue<Teuchos::ParameterList>(entry), name + "/", out);
    else out << name << " = " << entry.getAny(false) << '\n';
  }
}

std::string parameterListing(const Teuchos::ParameterList &deck) {
  std::ostringstream out;
  out.precision(17);
  listParameters(deck, "", out);
  return out.str();
}

// The Linear solver parameters that only an iterative solve uses.
const char *const kIterativeOnly[] = {
    "preconditioner", "MueLu smoother", "smoother degree", "vertex-patch levels", "patch sweeps",
    "Chebyshev eigenvalue method", "Chebyshev eigenvalue iterations", "Chebyshev eigenvalue ratio", "MueLu reuse",
    "MueLu reuse scope", "coarse size", "FROSch coarse space", "FROSch overlap", "Ifpack2 type"};
// The listing's 17 digits keep every value exact, so that a restart compares them exactly; a
// person reads 0.6, not 0.59999999999999998: each number of 16 or more digits in its shortest
// form that reads back as the same double.
std::string readable(const std::string &line) {
  static const std::regex number(R"([-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?)");
  std::string out;
  std::size_t done = 0;
  for (auto it = std::sregex_iterator(line.begin(), line.end(), number); it != std::sregex_iterator(); ++it) {
    const std::string token = it->str(), mantissa = (*it)[1].str();
    const auto digits = std::count_if(mantissa.begin(), mantissa.end(), [](char c) { return c >= '0' && c <= '9'; });
    out += line.substr(done, static_cast<std::size_t>(it->position()) - done);
    done = static_cast<std::size_t>(it->position()) + token.size();
    char buffer[32];
    const auto shortest = std::to_chars(buffer, buffer + sizeof buffer, std::strtod(token.c_str(), nullptr));
    out += digits >= 16 && shortest.ec == std::errc() ? std::string(buffer, shortest.ptr) : token;
  }
  return out + line.substr(done);
}
} // namespace

void declareSolverParameters(Teuchos::ParameterList &schema) {
  schema.set("Time", timeParameters(), "load/time stepping");
  schema.set("Incompressibility", incompressibilityParameters(), "the incompressibility algorithm");
  schema.set("Nonlinear solver", nonlinearSolverParameters(), "Newton's method (NOX)");
  schema.set("Linear solver", linearSolverParameters(), "Krylov solver and preconditioner (Belos, MueLu, Ifpack2, Amesos2)");
  schema.set("Output", outputParameters(), "result files");
  schema.set("Control", controlParameters(), "neural control of the muscle groups (paper §6.1)");
}

RunConfiguration parseRunConfiguration(const io::Deck &deck) {
  const Teuchos::ParameterList &D = deck.root();
  RunConfiguration c;
  c.deckFile = deck.file();
  c.time = parseTimeParameters(D.sublist("Time"));
  c.time.rampEndTime = deckEndTime(deck);
  checkDynamicsParameters(deck, c.time.dynamics);
  c.incompressibility = parseIncompressibilityParameters(D.sublist("Incompressibility"));
  c.newton = parseNewtonParameters(D.sublist("Nonlinear solver"));
  c.linear = parseLinearSolverParameters(D.sublist("Linear solver"));
  // The airflow coupled inside the Uzawa loop moves the loads by a coupling update between the
  // Newton solves of a step, a small change the step's first factors still precondition: kept for
  // the step, the supine tongue's coupled step fell from 2.72 to 1.67 times the explicit one
  // (doc/airflow.md, "Cost").
  if (!deck.given({"Linear solver", "direct reuse scope"}) && input::airflowCoupledInUzawaLoop(deck))
    c.linear.directReuseScope = ReuseScope::step;
  c.output = parseOutputParameters(D.sublist("Output"));
  // Named after the deck, so that runs of different decks from one directory do not share one.
  if (c.output.directory.empty())
    c.output.directory = (std::filesystem::path("results") / std::filesystem::path(deck.file()).stem()).string();
  c.controlled = controlRequested(D.sublist("Control"));
  // A nominal step below the minimum could never be taken: the run would start below the
  // step-size controller's floor (a step of 4.9e-324 s ran forever and counted its steps wrongly).
  if (c.time.steps.nominal < c.time.steps.minimum) {
    std::ostringstream why;
    why << deck.where({"Time", "step size"}) << " = " << c.time.steps.nominal << " s is below Time/minimum step size ("
        << c.time.steps.minimum << " s): no step could be taken; raise the step size or lower the minimum";
    throw io::DeckError(why.str());
  }
  c.listing = parameterListing(D);
  for (const char *name : kIterativeOnly)
    if (deck.given({"Linear solver", name})) c.givenIterativeOnly.push_back(deck.where({"Linear solver", name}));
  return c;
}

std::string firstListingDifference(const std::string &run, const std::string &now) {
  std::istringstream a(run), b(now);
  std::string l1, l2;
  while (true) {
    const bool more1 = static_cast<bool>(std::getline(a, l1)), more2 = static_cast<bool>(std::getline(b, l2));
    if (!more1 && !more2) return "";
    if (!more1 || !more2 || l1 != l2)
      return "the run's " + (more1 ? readable(l1) : "end") + ", now " + (more2 ? readable(l2) : "end");
  }
}

} // namespace glossa::solvers
