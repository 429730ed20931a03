#include "solvers/run/AirflowCoupling.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "contact/DeformablePair.hpp"
#include "loads/FollowerPressure.hpp"

namespace glossa::solvers {

namespace {
// The reference Gauss points of the airflow load's faces, where their pressures are read off.
std::vector<std::array<Eigen::Vector3d, 4>> gaussPoints(const model::Scene &scene) {
  const model::FollowerPressureLoad &load = scene.pressures.at(static_cast<std::size_t>(scene.airflowLoad));
  std::vector<std::array<Eigen::Vector3d, 4>> points;
  points.reserve(load.faces.size());
  for (const auto &face : load.faces) {
    const auto nodes = contact::faceNodeIds(scene.mesh, face);
    loads::FaceNodes X;
    for (int k = 0; k < 4; ++k) X.row(k) = scene.mesh.nodes[nodes[k]].transpose();
    points.push_back(loads::followerPressureGaussPoints(X));
  }
  return points;
}

airflow::AirSettings airOf(const input::AirflowParameters &p) {
  return {p.density, p.viscosity, p.recoveryCoefficient};
}

airflow::PressureMapping mappingOf(const input::AirflowParameters &p) {
  return p.mapping == input::AirflowMapping::linear ? airflow::PressureMapping::linear
                                                    : airflow::PressureMapping::nearestSection;
}

double largestChange(const Eigen::VectorXd &a, const Eigen::VectorXd &b) {
  return a.size() == 0 ? 0.0 : (a - b).cwiseAbs().maxCoeff();
}

Eigen::VectorXd asVector(const std::vector<double> &v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}
} // namespace

AirflowCoupling::AirflowCoupling(const input::AirflowParameters &parameters,
                                 std::shared_ptr<const model::AirwayOutput> airway, const model::Scene &scene)
    : parameters_(parameters), airway_(std::move(airway)), scene_(scene),
      flow_(airway_->lumen->centreline(), gaussPoints(scene), airOf(parameters), mappingOf(parameters)),
      facePressures_(scene.pressures.at(static_cast<std::size_t>(scene.airflowLoad)).given) {}

airflow::FlowDrive AirflowCoupling::drive(double time) const {
  airflow::FlowDrive d;
  d.nasalPressure = parameters_.nasalPressure(time);
  d.byFlowRate = parameters_.drive == input::AirflowDrive::flowRate;
  if (d.byFlowRate) d.flowRate = parameters_.flowRate(time);
  else d.trachealPressure = parameters_.trachealPressure(time);
  return d;
}

airflow::AirwayFlowState AirflowCoupling::measure(double time, const std::vector<double> &uAll) const {
  const airway::LumenState lumen = airway_->lumen->measure(airway_->positions(scene_.mesh, uAll));
  return flow_.solve(lumen, drive(time));
}

namespace {
void describe(const airflow::AirwayFlowState &f, AirflowStep &out) {
  out.flowRate = f.flow.flowRate;
  out.nasalPressure = f.flow.nasalPressure;
  out.trachealPressure = f.flow.trachealPressure;
  out.smallestArea = f.smallestArea;
  out.smallestSection = f.smallest;
  out.closed = f.flow.closed;
  out.choked = f.flow.choked;
}
} // namespace

AirflowStep AirflowCoupling::flowAt(double time, const std::vector<double> &uAll) const {
  AirflowStep out;
  out.on = true;
  try {
    const airflow::AirwayFlowState f = measure(time, uAll);
    describe(f, out);
    out.sectionPressure = f.sectionPressure;
    out.converged = true;
  } catch (const std::exception &e) {
    out.why = e.what();
  }
  return out;
}

AirflowStep AirflowCoupling::couple(double time, const std::vector<double> &uStart, const SolidSolve &solve,
                                    bool progress) const {
  AirflowStep out;
  out.on = true;
  airflow::CouplingIteration iteration(parameters_.couplingMethod, parameters_.relaxation);
  std::vector<double> uAll = uStart;
  try {
    // The first iterate: the flow through the lumen the step starts from.
    Eigen::VectorXd p = asVector(measure(time, uAll).sectionPressure);
    for (int k = 1; k <= parameters_.maximumCouplingIterations; ++k) {
      const std::vector<double> pk(p.data(), p.data() + p.size());
      *facePressures_ = flow_.facePressures(pk);
      out.iterations = k;
      if (!solve(uAll)) {
        out.why = "the solid's solve failed at coupling iteration " + std::to_string(k);
        return out;
      }
      const airflow::AirwayFlowState f = measure(time, uAll);
      const Eigen::VectorXd image = asVector(f.sectionPressure);
      out.residual = largestChange(image, p);
      out.residuals.push_back(out.residual);
      if (progress)
        std::printf("  airflow %d: flow rate %.6g L/s  smallest area %.4g mm^2%s  largest pressure change %.3e Pa\n", k,
                    1e3 * f.flow.flowRate, 1e6 * f.smallestArea, f.flow.closed ? " (closed)" : "", out.residual);
      if (out.residual <= parameters_.couplingTolerance) {
        describe(f, out);
        out.sectionPressure = pk; // what the solid carries; the flow's own are within the tolerance
        out.converged = true;
        return out;
      }
      p = iteration.next(p, image);
    }
  } catch (const std::exception &e) { // a lumen the flow cannot pass (same on every rank)
    out.why = std::string("the airflow: ") + e.what();
    return out;
  }
  char why[300];
  std::snprintf(why, sizeof why,
                "the airflow coupling did not converge in %d iterations ('maximum coupling iterations'): a section's "
                "pressure still changed by %.3g Pa, above the 'coupling tolerance' of %.3g Pa",
                parameters_.maximumCouplingIterations, out.residual, parameters_.couplingTolerance);
  out.why = why;
  return out;
}

} // namespace glossa::solvers
