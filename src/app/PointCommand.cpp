#include "app/PointCommand.hpp"

#include <fstream>
#include <stdexcept>

#include <Eigen/Dense>

#include "io/deck/DeckError.hpp"
#include "io/deck/ParameterSpec.hpp"
#include "io/output/RoundTripText.hpp"
#include "input/MaterialFactory.hpp"
#include "model/MuscleHistory.hpp"
#include "input/TimeFunctionParameters.hpp"
#include "solvers/parameters/TimeParameters.hpp"
#include "model/TimeFunction.hpp"

namespace glossa::app {

using Teuchos::Array;
using Teuchos::ParameterList;

ParameterList pointParameters() {
  ParameterList p;
  io::declareString(p, "path", "uniaxial", "deformation path of the material point (glossa point)",
                    {"uniaxial", "simple shear", "table"});
  io::declareDoubleArray(p, "direction", Array<double>({1.0, 0.0, 0.0}), "",
                         "e: the stretch direction (uniaxial) or shear direction (simple shear)", 3);
  io::declareDoubleArray(p, "shear plane normal", Array<double>({0.0, 1.0, 0.0}), "",
                         "m: normal of the shear planes (simple shear), orthogonal to e", 3);
  io::declareDouble(p, "amplitude", 0.2, "",
                    "lambda - 1 (uniaxial) or gamma (simple shear) at time-function value 1", io::Range::closed(-0.9, 10));
  p.set("time function", input::timeFunctionParameters(), "scales the amplitude in time");
  io::declareDoubleArray(p, "times", Array<double>(), "s", "table path: times of the rows (increasing)", 0);
  io::declareDoubleArray(p, "F", Array<double>(), "",
                         "table path: 9 values per time, F row-major (F11 F12 F13 F21 ...)", 0);
  io::declareDoubleArray(p, "position", Array<double>(3, 0.0), "m",
                         "where the point sits (for fibre direction fields that vary in space)", 3);
  return p;
}

namespace {

Eigen::Vector3d vec3(const Array<double> &a) { return {a[0], a[1], a[2]}; }

// The path F(t) of the deck's Point section.
class DeformationPath {
public:
  enum class Kind { uniaxial, simpleShear, table };

  // Parses and checks the Point section (its only reader).
  static DeformationPath fromDeck(const io::Deck &deck, double endTime) {
    const ParameterList &p = deck.root().sublist("Point");
    DeformationPath path;
    const auto kind = p.get<std::string>("path");
    path.kind_ = kind == "uniaxial" ? Kind::uniaxial : kind == "simple shear" ? Kind::simpleShear : Kind::table;
    path.e_ = vec3(p.get<Array<double>>("direction"));
    path.m_ = vec3(p.get<Array<double>>("shear plane normal"));
    path.amplitude_ = p.get<double>("amplitude");
    path.scale_ = input::parseTimeFunction(p.sublist("time function"), endTime);
    path.position_ = vec3(p.get<Array<double>>("position"));
    if (!(path.e_.norm() > 0.0)) throw io::DeckError(deck.where({"Point", "direction"}) + " is zero");
    path.e_.normalize();
    if (path.kind_ == Kind::simpleShear) {
      if (!(path.m_.norm() > 0.0) || std::abs(path.e_.dot(path.m_.normalized())) > 1e-12)
        throw io::DeckError(deck.where({"Point", "shear plane normal"}) +
                            " must be non-zero and orthogonal to 'direction'");
      path.m_.normalize();
    }
    if (path.kind_ == Kind::table) path.readTable(deck, p.get<Array<double>>("times"), p.get<Array<double>>("F"));
    return path;
  }

  double parameter(double t) const { return kind_ == Kind::table ? 0.0 : amplitude_ * scale_(t); }

  Eigen::Matrix3d operator()(double t) const {
    if (kind_ == Kind::uniaxial) {
      const double lambda = 1.0 + parameter(t);
      const Eigen::Matrix3d ee = e_ * e_.transpose();
      return lambda * ee + (Eigen::Matrix3d::Identity() - ee) / std::sqrt(lambda);
    }
    if (kind_ == Kind::simpleShear) return Eigen::Matrix3d::Identity() + parameter(t) * e_ * m_.transpose();
    if (t <= times_.front()) return table_.front();
    for (std::size_t k = 1; k < times_.size(); ++k)
      if (t <= times_[k]) {
        const double s = (t - times_[k - 1]) / (times_[k] - times_[k - 1]);
        return (1 - s) * table_[k - 1] + s * table_[k];
      }
    return table_.back();
  }

  const Eigen::Vector3d &direction() const { return e_; }
  const Eigen::Vector3d &position() const { return position_; }

private:
  void readTable(const io::Deck &deck, const Array<double> &t, const Array<double> &F) {
    if (t.empty() || F.size() != 9 * t.size())
      throw io::DeckError(deck.where({"Point", "F"}) + ": needs 9 values per entry of 'times' (" +
                          std::to_string(t.size()) + " times, " + std::to_string(F.size()) + " values)");
    for (Teuchos::Array<double>::size_type k = 0; k < t.size(); ++k) {
      if (k > 0 && !(t[k] > t[k - 1])) throw io::DeckError(deck.where({"Point", "times"}) + " must increase strictly");
      Eigen::Matrix3d M;
      for (int i = 0; i < 9; ++i) M(i / 3, i % 3) = F[9 * k + i];
      if (!(M.determinant() > 0.0))
        throw io::DeckError(deck.where({"Point", "F"}) + ": row " + std::to_string(k) + " has det F <= 0");
      times_.push_back(t[k]);
      table_.push_back(M);
    }
  }

  Kind kind_ = Kind::uniaxial;
  Eigen::Vector3d e_, m_, position_;
  double amplitude_ = 0.0;
  model::TimeFunction scale_ = model::TimeFunction::constant();
  std::vector<double> times_;
  std::vector<Eigen::Matrix3d> table_;
};

} // namespace

int runPointDriver(const io::Deck &deck, const std::filesystem::path &csv) {
  const solvers::StepSizeRule steps = solvers::parseTimeParameters(deck.root().sublist("Time")).steps;
  const double endTime = steps.endTime, nominal = std::min(steps.nominal, endTime);
  const DeformationPath path = DeformationPath::fromDeck(deck, endTime);
  // The Material section at the point (its fibre direction fields evaluated at the position).
  const input::BuiltMaterial material = input::buildPointMaterial(deck, path.position(), endTime);
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
  const Eigen::Vector3d &e = path.direction();
  const Eigen::Vector3d t1 = e.unitOrthogonal(), t2 = e.cross(t1);
  int rows = 0;
  auto write = [&](double t, const materials::PointResponse &r, const materials::MusclePointResponse *m) {
    const Eigen::Matrix3d F = path(t);
    const Eigen::Matrix3d sigma = r.P * F.transpose() / F.determinant();
    const double axial = e.dot(sigma * e) - 0.5 * (t1.dot(sigma * t1) + t2.dot(sigma * t2));
    out << io::roundTripText(t) << ',' << io::roundTripText(path.parameter(t)) << ',' << io::roundTripText(r.energy);
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
