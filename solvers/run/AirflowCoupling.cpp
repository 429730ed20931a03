#include "solvers/run/AirflowCoupling.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "airway/ResponseProbe.hpp"
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
  return flow_.solve(airway_->measure(scene_.mesh, uAll), drive(time));
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

void AirflowCoupling::setFacePressures(const Eigen::VectorXd &sectionPressure) const {
  *facePressures_ = flow_.facePressures(std::vector<double>(sectionPressure.data(), sectionPressure.data() + sectionPressure.size()));
}

void AirflowCoupling::showPressures(const std::vector<double> &sectionPressure) const {
  *facePressures_ = flow_.facePressures(sectionPressure);
}

AirflowCoupling::StepCoupling::StepCoupling(const AirflowCoupling &coupling, double time,
                                            const std::vector<double> &uStart, bool progress)
    : coupling_(coupling), time_(time), progress_(progress),
      iteration_(coupling.parameters_.couplingMethod, coupling.parameters_.relaxation) {
  result_.on = true;
  try { // the first iterate: the flow through the lumen the step starts from
    pressure_ = asVector(coupling_.measure(time, uStart).sectionPressure);
    coupling_.setFacePressures(pressure_);
  } catch (const std::exception &e) { // a lumen the flow cannot pass (the same on every rank)
    result_.why = std::string("the airflow: ") + e.what();
  }
}

void AirflowCoupling::forEachUnitSectionPressure(const std::function<void(std::size_t)> &visit) const {
  const std::vector<std::array<double, 4>> kept = *facePressures_;
  std::vector<double> unit(numSections(), 0.0);
  try {
    for (std::size_t i = 0; i < unit.size(); ++i) {
      unit[i] = 1.0;
      *facePressures_ = flow_.facePressures(unit);
      unit[i] = 0.0;
      visit(i);
    }
  } catch (...) {
    *facePressures_ = kept;
    throw;
  }
  *facePressures_ = kept;
}

Eigen::MatrixXd AirflowCoupling::mapJacobian(double time, const std::vector<double> &uAll, const Eigen::VectorXd &image,
                                             const std::vector<std::vector<double>> &responses) const {
  const auto n = static_cast<Eigen::Index>(numSections());
  Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i < n && static_cast<std::size_t>(i) < responses.size(); ++i) {
    const std::vector<double> &du = responses[static_cast<std::size_t>(i)];
    const double step = airway::probeStep(du); // [Pa]
    if (!(step > 0.0) || du.size() != uAll.size()) continue; // a section without faces
    try {
      jacobian.col(i) = (asVector(measure(time, airway::probed(uAll, du, step)).sectionPressure) - image) / step;
    } catch (const std::exception &) { // the probe's lumen shut or lost a section: no slope there
    }
  }
  return jacobian;
}

AirflowCoupling::StepCoupling::Verdict AirflowCoupling::StepCoupling::afterSolve(const std::vector<double> &uAll,
                                                                                const SectionResponses &responses) {
  const input::AirflowParameters &parameters = coupling_.parameters_;
  ++result_.iterations;
  try {
    const airflow::AirwayFlowState f = coupling_.measure(time_, uAll);
    const Eigen::VectorXd image = asVector(f.sectionPressure);
    result_.residual = largestChange(image, pressure_);
    if (progress_)
      std::printf("  airflow %d: flow rate %.6g L/s  smallest area %.4g mm^2%s  largest pressure change %.3e Pa\n",
                  result_.iterations, 1e3 * f.flow.flowRate, 1e6 * f.smallestArea, f.flow.closed ? " (closed)" : "",
                  result_.residual);
    if (result_.residual <= parameters.couplingTolerance) {
      describe(f, result_);
      // What the solid carries; the flow's own pressures are within the tolerance of them.
      result_.sectionPressure.assign(pressure_.data(), pressure_.data() + pressure_.size());
      result_.converged = true;
      return Verdict::coupled;
    }
    if (result_.iterations >= parameters.maximumCouplingIterations) {
      char why[300];
      std::snprintf(why, sizeof why,
                    "the airflow coupling did not converge in %d iterations ('maximum coupling iterations'): a "
                    "section's pressure still changed by %.3g Pa, above the 'coupling tolerance' of %.3g Pa",
                    parameters.maximumCouplingIterations, result_.residual, parameters.couplingTolerance);
      result_.why = why;
      return Verdict::failed;
    }
    if (iteration_.needsJacobian() && responses) {
      try {
        iteration_.setJacobian(coupling_.mapJacobian(time_, uAll, image, responses()));
      } catch (const std::exception &) { // no tangent solve (it failed, or the mixed method has none, on
      }                                    // every rank alike): this update relaxes, the next asks again
    }
    pressure_ = iteration_.next(pressure_, image);
    coupling_.setFacePressures(pressure_);
    return Verdict::again;
  } catch (const std::exception &e) {
    result_.why = std::string("the airflow: ") + e.what();
    return Verdict::failed;
  }
}

AirflowStep AirflowCoupling::couple(double time, const std::vector<double> &uStart, const SolidSolve &solve,
                                    bool progress, const StepCoupling::SectionResponses &responses) const {
  StepCoupling step(*this, time, uStart, progress);
  if (!step.started()) return step.result();
  std::vector<double> uAll = uStart;
  for (;;) {
    if (!solve(uAll)) {
      AirflowStep out = step.result();
      out.why = "the solid's solve failed at coupling iteration " + std::to_string(out.iterations + 1);
      return out;
    }
    if (step.afterSolve(uAll, responses) != StepCoupling::Verdict::again) return step.result();
  }
}

} // namespace glossa::solvers
