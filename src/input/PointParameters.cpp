#include "input/PointParameters.hpp"

#include <cmath>
#include <string>

#include <Eigen/Dense>

#include "input/TimeFunctionParameters.hpp"
#include "input/DeckVector.hpp"
#include "io/deck/DeckError.hpp"
#include "io/deck/ParameterSpec.hpp"

namespace glossa::input {

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
  p.set("time function", timeFunctionParameters(), "scales the amplitude in time");
  io::declareDoubleArray(p, "times", Array<double>(), "s", "table path: times of the rows (increasing)", 0);
  io::declareDoubleArray(p, "F", Array<double>(), "",
                         "table path: 9 values per time, F row-major (F11 F12 F13 F21 ...)", 0);
  io::declareDoubleArray(p, "position", Array<double>(3, 0.0), "m",
                         "where the point sits (for fibre direction fields that vary in space)", 3);
  return p;
}

namespace {

// The table path's rows: 9 values of F per time, times strictly increasing, det F > 0.
void readTable(const io::Deck &deck, const Array<double> &t, const Array<double> &F, PointParameters &point) {
  if (t.empty() || F.size() != 9 * t.size())
    throw io::DeckError(deck.where({"Point", "F"}) + ": needs 9 values per entry of 'times' (" +
                        std::to_string(t.size()) + " times, " + std::to_string(F.size()) + " values)");
  for (Array<double>::size_type k = 0; k < t.size(); ++k) {
    if (k > 0 && !(t[k] > t[k - 1])) throw io::DeckError(deck.where({"Point", "times"}) + " must increase strictly");
    Eigen::Matrix3d M;
    for (int i = 0; i < 9; ++i) M(i / 3, i % 3) = F[9 * k + i];
    if (!(M.determinant() > 0.0))
      throw io::DeckError(deck.where({"Point", "F"}) + ": row " + std::to_string(k) + " has det F <= 0");
    point.times.push_back(t[k]);
    point.table.push_back(M);
  }
}

} // namespace

PointParameters parsePointParameters(const io::Deck &deck, double endTime) {
  const ParameterList &p = deck.root().sublist("Point");
  PointParameters point;
  const auto path = p.get<std::string>("path");
  point.path = path == "uniaxial" ? PointPath::uniaxial : path == "simple shear" ? PointPath::simpleShear : PointPath::table;
  point.direction = vec3(p.get<Array<double>>("direction"));
  point.shearPlaneNormal = vec3(p.get<Array<double>>("shear plane normal"));
  point.amplitude = p.get<double>("amplitude");
  refuseUnreadTimeFunctionParameters(deck, {"Point", "time function"});
  point.scale = parseTimeFunction(p.sublist("time function"), endTime);
  point.position = vec3(p.get<Array<double>>("position"));
  if (!(point.direction.norm() > 0.0)) throw io::DeckError(deck.where({"Point", "direction"}) + " is zero");
  point.direction.normalize();
  if (point.path == PointPath::simpleShear) {
    const Eigen::Vector3d &m = point.shearPlaneNormal;
    if (!(m.norm() > 0.0) || std::abs(point.direction.dot(m.normalized())) > 1e-12)
      throw io::DeckError(deck.where({"Point", "shear plane normal"}) +
                          " must be non-zero and orthogonal to 'direction'");
    point.shearPlaneNormal.normalize();
  }
  if (point.path == PointPath::table) readTable(deck, p.get<Array<double>>("times"), p.get<Array<double>>("F"), point);
  return point;
}

} // namespace glossa::input
