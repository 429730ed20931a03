#include "solvers/ControlSensitivity.hpp"

namespace glossa::solvers {

ControlPointSensitivity controlPointSensitivity(assembly::Assembler &assembler, const NewtonSolver &newton,
                                                const assembly::Vector &u, const std::vector<double> &lambda,
                                                double time, const std::vector<int> &groups,
                                                const std::vector<mesh::NodeId> &points) {
  model::MuscleHistory &history = assembler.muscleHistory();
  const auto n = groups.size();
  assembly::MultiVector rhs(assembler.ownedMap(), n), x(assembler.ownedMap(), n);
  // Step in alpha: truncation O(h^2) and round-off O(eps / h) of the residual's scale balance
  // near 1e-5; one-sided three-point differences keep alpha inside [0, 1].
  constexpr double h = 1e-5;
  assembly::Vector f(assembler.ownedMap());
  for (std::size_t j = 0; j < n; ++j) {
    const int g = groups[j];
    const double alpha = history.trialActivation()[g];
    const double side = alpha + 2.0 * h <= 1.0 ? 1.0 : -1.0;
    auto column = rhs.getVectorNonConst(j);
    const double weights[3] = {-1.5, 2.0, -0.5}; // d/da at a of f(a), f(a + s h), f(a + 2 s h)
    for (int k = 0; k < 3; ++k) {
      history.setTrialActivation(g, alpha + side * k * h);
      const auto status = assembler.assemble(u, time, lambda, nullptr, &f, nullptr);
      if (!status.valid) throw std::runtime_error("sensitivity: the converged state is inadmissible");
      column->update(-weights[k] * side / h * history.trialActivationInputDerivative(g), f, 1.0);
    }
    history.setTrialActivation(g, alpha);
  }
  ControlPointSensitivity out;
  out.krylovIterations = newton.solveTangent(u, rhs, x);
  out.dxdu.resize(3 * static_cast<Eigen::Index>(points.size()), static_cast<Eigen::Index>(n));
  for (std::size_t j = 0; j < n; ++j) {
    const std::vector<double> all = assembler.gatherDisplacement(*x.getVector(j));
    for (std::size_t p = 0; p < points.size(); ++p)
      for (int c = 0; c < 3; ++c)
        out.dxdu(3 * static_cast<Eigen::Index>(p) + c, static_cast<Eigen::Index>(j)) = all[3 * points[p] + c];
  }
  return out;
}

} // namespace glossa::solvers
