#include "input/AirflowParameters.hpp"

#include <string>

#include "input/TimeFunctionParameters.hpp"
#include "input/UnreadParameters.hpp"
#include "io/deck/ParameterSpec.hpp"

namespace glossa::input {
namespace {

const char *const kDrivenBy = "driven by";

// A value and the time function that scales it, e.g. "nasal pressure" and "nasal pressure time function".
void declareScaled(Teuchos::ParameterList &p, const std::string &name, const std::string &unit, const std::string &doc) {
  io::declareDouble(p, name, 0.0, unit, doc + ", times '" + name + " time function'");
  p.set(name + " time function", timeFunctionParameters("constant"), "scales '" + name + "' in time");
}

model::TimeFunction scaledAt(const io::Deck &deck, const std::string &name, double endTime) {
  const double value = deck.root().sublist("Airflow").get<double>(name);
  return timeFunctionAt(deck, {"Airflow", name + " time function"}, endTime).scaled(value);
}

}  // namespace

Teuchos::ParameterList airflowParameters() {
  Teuchos::ParameterList p;
  io::declareString(p, kDrivenBy, "off",
                    "off: no airflow; pressures: the nasal and tracheal pressures drive the flow; flow rate: the "
                    "nasal pressure and a flow rate give the pressures (doc/airflow.md)",
                    {"off", "pressures", "flow rate"});
  declareScaled(p, "nasal pressure", "Pa", "the pressure of the air at rest upstream of the airway's nasal end");
  declareScaled(p, "tracheal pressure", "Pa", "pressures: the static pressure at the airway's tracheal end");
  declareScaled(p, "flow rate", "m^3/s", "flow rate: the volume flow from the nasal end to the tracheal end");
  io::declareDouble(p, "air density", 1.2, "kg/m^3", "the air's density", io::Range::positive());
  io::declareDouble(p, "air viscosity", 1.8e-5, "Pa s", "the air's dynamic viscosity (0: no viscous loss)",
                    io::Range::nonNegative());
  io::declareDouble(p, "recovery coefficient", 0.0, "",
                    "the share of Bernoulli's pressure rise recovered past the narrowest section (0: the jet "
                    "separates and none is; 1: all is)",
                    io::Range::closed(0.0, 1.0));
  io::declareString(p, "pressure mapping", "linear",
                    "the pressure on a face from its arc length along the centreline: linear between the two "
                    "sections around it, or the nearest section's",
                    {"linear", "nearest section"});
  io::declareDouble(p, "coupling tolerance", 0.1, "Pa",
                    "the flow and the solid are coupled when no section's pressure changes by more than this "
                    "between two coupling iterations",
                    io::Range::positive());
  io::declareString(p, "coupling loop", "Uzawa loop",
                    "where the coupling iterates: Uzawa loop: one coupling iteration after every Newton solve, "
                    "beside the update of the volume multipliers; step solve: one after every converged step "
                    "solve (doc/airflow.md)",
                    {"Uzawa loop", "step solve"});
  io::declareString(p, "coupling method", "Aitken",
                    "how the sections' pressures are updated between coupling iterations: Aitken's dynamic "
                    "relaxation, constant relaxation, the interface quasi-Newton method IQN-ILS, or Newton's method "
                    "with the Jacobian measured through the solid's tangent once a step (doc/airflow.md)",
                    {"Aitken", "constant relaxation", "quasi-Newton", "Newton"});
  io::declareDouble(p, "relaxation", 0.5, "",
                    "the relaxation of the sections' pressures: constant relaxation's factor, Aitken's and the "
                    "quasi-Newton method's first one (later ones adapt it)",
                    {0.0, 1.0, true, false});
  io::declareInt(p, "maximum coupling iterations", 30, "coupling iterations of a step before it is cut back",
                 io::Range::closed(1, 1000));
  return p;
}

namespace {
AirflowLoop loopOf(const Teuchos::ParameterList &a) {
  return a.get<std::string>("coupling loop") == "Uzawa loop" ? AirflowLoop::uzawaLoop : AirflowLoop::stepSolve;
}
} // namespace

bool airflowCoupledInUzawaLoop(const io::Deck &deck) {
  if (!deck.root().isSublist("Airflow")) return false;
  const Teuchos::ParameterList &a = deck.root().sublist("Airflow");
  return a.get<std::string>(kDrivenBy) != "off" && loopOf(a) == AirflowLoop::uzawaLoop;
}

AirflowParameters parseAirflowParameters(const io::Deck &deck, double endTime) {
  static const std::vector<std::string> driven{"pressures", "flow rate"};
  static const std::vector<ReadUnder> readers{{"nasal pressure", driven},
                                              {"nasal pressure time function", driven},
                                              {"tracheal pressure", {"pressures"}},
                                              {"tracheal pressure time function", {"pressures"}},
                                              {"flow rate", {"flow rate"}},
                                              {"flow rate time function", {"flow rate"}},
                                              {"air density", driven},
                                              {"air viscosity", driven},
                                              {"recovery coefficient", driven},
                                              {"pressure mapping", driven},
                                              {"coupling tolerance", driven},
                                              {"coupling loop", driven},
                                              {"coupling method", driven},
                                              {"relaxation", driven},
                                              {"maximum coupling iterations", driven}};
  refuseUnreadParameters(deck, {"Airflow"}, kDrivenBy, readers);
  const Teuchos::ParameterList &a = deck.root().sublist("Airflow");
  AirflowParameters p;
  const auto drive = a.get<std::string>(kDrivenBy);
  if (drive == "off") return p;
  p.drive = drive == "pressures" ? AirflowDrive::pressures : AirflowDrive::flowRate;
  p.nasalPressure = scaledAt(deck, "nasal pressure", endTime);
  if (p.drive == AirflowDrive::pressures)
    p.trachealPressure = scaledAt(deck, "tracheal pressure", endTime);
  else
    p.flowRate = scaledAt(deck, "flow rate", endTime);
  p.density = a.get<double>("air density");
  p.viscosity = a.get<double>("air viscosity");
  p.recoveryCoefficient = a.get<double>("recovery coefficient");
  p.mapping = a.get<std::string>("pressure mapping") == "linear" ? AirflowMapping::linear : AirflowMapping::nearestSection;
  p.couplingTolerance = a.get<double>("coupling tolerance");
  p.loop = loopOf(a);
  const auto method = a.get<std::string>("coupling method");
  p.couplingMethod = method == "Aitken"                ? airflow::CouplingMethod::aitken
                     : method == "constant relaxation" ? airflow::CouplingMethod::constantRelaxation
                     : method == "quasi-Newton"        ? airflow::CouplingMethod::quasiNewton
                                                       : airflow::CouplingMethod::newton;
  p.relaxation = a.get<double>("relaxation");
  p.maximumCouplingIterations = a.get<int>("maximum coupling iterations");
  return p;
}

}  // namespace glossa::input
