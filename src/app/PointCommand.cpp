#include "app/PointCommand.hpp"

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include <Eigen/Dense>

#include "app/DeformationPath.hpp"
#include "input/MaterialFactory.hpp"
#include "input/PointParameters.hpp"
#include "io/output/RoundTripText.hpp"
#include "model/MuscleHistory.hpp"

namespace glossa::app {

int runPointDriver(const io::Deck &deck, const solvers::TimeParameters &time, const std::filesystem::path &csv) {
  const double endTime = time.steps.endTime, nominal = std::min(time.steps.nominal, endTime);
  const input::PointParameters point = input::parsePointParameters(deck, time.rampEndTime);
  auto path = [&point](double t) { return deformationGradient(point, t); };
  // The Material section at the point (its fibre direction fields evaluated at the position).
  const input::BuiltMaterial material = input::buildPointMaterial(deck, point.position, time.rampEndTime);
  const model::MuscleArchitecture &muscles = material.muscles;

  model::MuscleHistory history(muscles, {0});
  const int region = muscles.hasFibres() ? muscles.elementRegion[0] : -1;
  const materials::MuscleMaterial *law = region >= 0 ? muscles.regions[region].law.get() : nullptr;
  const int families = law ? law->familyCount() : 0;

  if (csv.has_parent_path()) std::filesystem::create_directories(csv.parent_path());
  std::ofstream out(csv);
  if (!out) throw std::runtime_error("cannot write " + csv.string());
  out << "time [s],path_parameter [-],energy [J/m^3],sigma_xx [Pa],sigma_yy [Pa],sigma_zz [Pa],sigma_xy [Pa],"
         "sigma_yz [Pa],sigma_xz [Pa],axial_stress [Pa]";
  for (int f = 0; f < families; ++f) {
    const auto &name = muscles.regions[region].familyNames[f];
    out << ",lambda_f_" << name << " [-],lambda_c_" << name << " [-],T_" << name << " [Pa]";
  }
  for (const auto &g : muscles.groups) out << ",alpha_" << g.name << " [-]";
  out << '\n';

  // Two unit vectors orthogonal to e, for the axial stress.
  const Eigen::Vector3d &e = point.direction;
  const Eigen::Vector3d t1 = e.unitOrthogonal(), t2 = e.cross(t1);
  int rows = 0;
  auto write = [&](double t, const materials::PointResponse &r, const materials::MusclePointResponse *m) {
    const Eigen::Matrix3d F = path(t);
    const Eigen::Matrix3d sigma = r.P * F.transpose() / F.determinant();
    const double axial = e.dot(sigma * e) - 0.5 * (t1.dot(sigma * t1) + t2.dot(sigma * t2));
    out << io::roundTripText(t) << ',' << io::roundTripText(pathParameter(point, t)) << ',' << io::roundTripText(r.energy);
    for (const auto &[i, j] : {std::pair{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}})
      out << ',' << io::roundTripText(sigma(i, j));
    out << ',' << io::roundTripText(axial);
    for (int f = 0; f < families; ++f)
      out << ',' << io::roundTripText(m->lambdaF(f)) << ',' << io::roundTripText(m->lambdaC(f)) << ','
          << io::roundTripText(m->T(f));
    for (double a : history.trialActivation()) out << ',' << io::roundTripText(a);
    out << '\n';
    ++rows;
  };
  auto evaluate = [&](double t, double dt, materials::MusclePointResponse &m) {
    materials::PointResponse r;
    if (!law) {
      r = material.tissues[0].matrix->evaluate(path(t));
      return r;
    }
    materials::MusclePointInput in;
    in.F = path(t);
    in.dt = dt;
    in.alpha = history.familyActivation(0);
    in.lambdaCOld = Eigen::Map<const Eigen::VectorXd>(history.committedLambdaC(0, 0), families);
    in.directions = muscles.directions[0];
    m = law->evaluate(in);
    if (!m.ok())
      throw std::runtime_error("glossa point: the point law failed at t = " + std::to_string(t) + " (family " +
                               std::to_string(m.failedFamily) + "): " + materials::describe(m.status));
    r.energy = m.energy;
    r.P = m.P;
    return r;
  };

  materials::MusclePointResponse m;
  m.lambdaC = m.lambdaF = m.T = materials::FamilyValues::Ones(families);
  write(0.0, evaluate(0.0, nominal, m), &m);
  for (double t = 0.0; t < endTime * (1 - 1e-12);) {
    const double dt = endTime - t < 1.0001 * nominal ? endTime - t : nominal;
    t += dt;
    history.beginStep(t, dt);
    const materials::PointResponse r = evaluate(t, dt, m);
    for (int f = 0; f < families; ++f)
      for (int q = 0; q < 8; ++q) history.trialLambdaC(0, q)[f] = m.lambdaC(f);
    write(t, r, &m);
    history.commit();
  }
  out.flush();
  if (!out) throw std::runtime_error("cannot write " + csv.string());
  return rows;
}

} // namespace glossa::app
