#include "solvers/parameters/LinearSolverChoice.hpp"

namespace glossa::solvers {

LinearSolverChoice parseLinearSolverChoice(const Teuchos::ParameterList &s) {
  LinearSolverChoice c;
  const std::string type = s.get<std::string>("type");
  c.type = type == "direct" ? LinearSolverType::direct : type == "iterative" ? LinearSolverType::iterative : LinearSolverType::automatic;
  c.tolerance = s.get<double>("tolerance");
  c.keptForTheRun = s.get<std::string>("MueLu reuse scope") == "run";
  c.directSolver = s.get<std::string>("direct solver");
  c.preconditioner = s.get<std::string>("preconditioner");
  return c;
}

} // namespace glossa::solvers
