#include "solvers/parameters/TimeParameters.hpp"

#include <cmath>

#include "io/deck/DeckError.hpp"
#include "io/deck/ParameterSpec.hpp"
#include "io/deck/SpaceTimeExpression.hpp"

namespace glossa::solvers {

Teuchos::ParameterList timeParameters() {
  Teuchos::ParameterList p;
  io::declareDouble(p, "end time", 1.0, "s", "time of the last step; a ramp of duration 0 spans the deck file's end time even when "
                    "--set changes this one (doc/loads.md)", io::Range::positive());
  io::declareDouble(p, "step size", 0.1, "s", "nominal step", io::Range::positive());
  io::declareDouble(p, "minimum step size", 1e-6, "s",
                    "the run stops (and says why) when a failing step would be cut below this",
                    io::Range::positive());
  io::declareString(
      p, "predictor", "auto",
      "where each step's Newton iteration (and every candidate solve of a controlled step) "
      "starts: none (the last committed state), linear extrapolation (the last two committed "
      "states, displacement and multipliers, extrapolated to the new time; the same for every "
      "candidate, so control groups still agree bit for bit; a step that fails from there is "
      "tried once more from the committed state before it is cut back) or auto (linear "
      "extrapolation, but none with Incompressibility/method = penalty, whose kappa multiplies "
      "the extrapolation's volume error: step-44 block 8^3 65 -> 69 Newton iterations; and none "
      "under the GA controller, whose candidates start from its seed solve: the medium tongue's "
      "seed fails from the extrapolated start, doc/control.md). "
      "Measured on 24 scenes: 21-26 % fewer Newton iterations on the §7.1 blocks, 11 % fewer "
      "Krylov iterations on the step-44 block, 16 steps instead of 24 on the styloglossus "
      "scene, at most 9 % more Newton iterations elsewhere: bench/README.md",
      {"auto", "none", "linear extrapolation"});
  io::declareString(p, "at a limit point", "stop",
                    "stop: after each converged step the tangent's stiffness along the load path is measured "
                    "(one tangent solve; a path driven by activation alone has no load rate and is not "
                    "measured); a state past a limit point (negative stiffness: an unstable "
                    "equilibrium, e.g. the far branch of an inflated sphere) is refused, the step is cut back "
                    "until the limit point is bracketed to the tolerance below, and the run stops naming it "
                    "(summary.json: limit_point); ignore: no measurement, any converged state is accepted "
                    "(the mixed method never measures: doc/theory.md); follow: as stop, then the run goes on "
                    "from the last accepted state past the limit point by arc-length continuation (as Time/path "
                    "following = arc length, with what that needs)",
                    {"stop", "ignore", "follow"});
  io::declareString(p, "path following", "load control",
                    "load control: the time advances by the step size and every load follows it; arc length: "
                    "the time, which scales every load, becomes an unknown beside the displacement and each "
                    "step has a set length along the path (Trilinos LOCA's pseudo arc length, tangent "
                    "predictor, adaptive step up to 'step size', down to 'minimum step size'), so the path "
                    "passes a load maximum and follows the falling branch (doc/theory.md); needs "
                    "Incompressibility/method = penalty, no muscle groups, no controller and supports "
                    "that prescribe no motion; a run is not restarted",
                    {"load control", "arc length"});
  io::declareInt(p, "arc length steps", 200, "arc length: the most continuation steps before the run stops",
                 io::Range::closed(1, 100000));
  io::declareDouble(p, "stop at displacement", 0.0, "m",
                    "arc length: the path ends once some node has moved this far (0: only at the end time or "
                    "back at t = 0)", io::Range::atLeast(0.0));
  io::declareDouble(p, "limit point tolerance", 0.01, "",
                    "a limit point is located once the bracket's step is below this fraction of the nominal "
                    "step size", io::Range::open(0.0, 1.0));
  io::declareString(p, "analysis", "static",
                    "static: quasi-static steps, no inertia; dynamic: M a + C v + f_int = f_ext by generalized-alpha "
                    "(Chung-Hulbert), velocities and accelerations in the state, the fields and the checkpoint, "
                    "energy.csv (doc/dynamics.md)",
                    {"static", "dynamic"});
  io::declareString(p, "integrator", "generalized-alpha",
                    "dynamic: generalized-alpha (second order, its dissipation set by the spectral radius) or "
                    "backward Euler (first order, L-stable: a resolved mode loses about pi w dt of its log-amplitude "
                    "a period; for stiff cases where the motion, not its oscillation, matters) or energy conserving "
                    "(the trapezoidal rule with each element's force a discrete gradient of its stored energy: kinetic "
                    "plus stored energy conserved to the solver's tolerance, for nearly incompressible vibration "
                    "where the trapezoidal rule gains energy; doc/dynamics.md)",
                    {"generalized-alpha", "backward Euler", "energy conserving"});
  io::declareDouble(p, "spectral radius", 1.0, "",
                    "dynamic: generalized-alpha's spectral radius at infinite frequency rho_inf; 1 is Newmark's "
                    "trapezoidal rule (no numerical dissipation, energy conserved in linear problems), smaller "
                    "values damp the modes a step does not resolve while staying second order",
                    io::Range::closed(0.0, 1.0));
  io::declareString(p, "mass matrix", "consistent",
                    "dynamic: consistent (int rho N_a N_b dV) or lumped (its row sums on the diagonal); each "
                    "element at its tissue's density",
                    {"consistent", "lumped"});
  io::declareDouble(p, "Rayleigh mass coefficient", 0.0, "1/s",
                    "dynamic: alpha of the damping C = alpha M + beta K_0", io::Range::atLeast(0.0));
  io::declareDouble(p, "Rayleigh stiffness coefficient", 0.0, "s",
                    "dynamic: beta of the damping C = alpha M + beta K_0 (K_0 the tangent at the initial state)",
                    io::Range::atLeast(0.0));
  for (const char *name : {"initial vx", "initial vy", "initial vz"})
    io::declareString(p, name, "0",
                      "dynamic: the velocity component at t = 0 [m/s] as an expression of the reference position "
                      "X, Y, Z [m] (e.g. \"0.01 * X / 0.05\"); at supported components the support's own rate");
  return p;
}

TimeParameters parseTimeParameters(const Teuchos::ParameterList &s) {
  TimeParameters t;
  t.steps = {s.get<double>("end time"), s.get<double>("step size"), s.get<double>("minimum step size")};
  t.rampEndTime = t.steps.endTime;
  const std::string predictor = s.get<std::string>("predictor");
  t.predictor = predictor == "linear extrapolation" ? Predictor::linearExtrapolation
                : predictor == "none"                 ? Predictor::none
                                                      : Predictor::automatic;
  const std::string atLimit = s.get<std::string>("at a limit point");
  t.atLimitPoint = atLimit == "stop" ? AtLimitPoint::stop : atLimit == "ignore" ? AtLimitPoint::ignore : AtLimitPoint::follow;
  t.limitPointTolerance = s.get<double>("limit point tolerance");
  t.pathFollowing = s.get<std::string>("path following") == "arc length" ? PathFollowing::arcLength : PathFollowing::loadControl;
  t.arcLengthSteps = s.get<int>("arc length steps");
  t.stopAtDisplacement = s.get<double>("stop at displacement");
  DynamicsParameters &d = t.dynamics;
  d.analysis = s.get<std::string>("analysis") == "dynamic" ? Analysis::dynamic : Analysis::quasiStatic;
  const std::string integrator = s.get<std::string>("integrator");
  d.integrator = integrator == "backward Euler"      ? Integrator::backwardEuler
                 : integrator == "energy conserving" ? Integrator::energyConserving
                                                     : Integrator::generalizedAlpha;
  d.spectralRadius = s.get<double>("spectral radius");
  d.mass = s.get<std::string>("mass matrix") == "lumped" ? fem::MassLumping::lumped : fem::MassLumping::consistent;
  d.rayleighMass = s.get<double>("Rayleigh mass coefficient");
  d.rayleighStiffness = s.get<double>("Rayleigh stiffness coefficient");
  d.initialVelocity = {s.get<std::string>("initial vx"), s.get<std::string>("initial vy"),
                       s.get<std::string>("initial vz")};
  return t;
}

void checkDynamicsParameters(const io::Deck &deck, const DynamicsParameters &dynamics) {
  static const char *const kDynamicOnly[] = {"integrator", "spectral radius", "mass matrix", "Rayleigh mass coefficient",
                                              "Rayleigh stiffness coefficient", "initial vx", "initial vy",
                                              "initial vz"};
  if (!dynamics.dynamic()) {
    for (const char *name : kDynamicOnly)
      if (deck.given({"Time", name}))
        throw io::DeckError(deck.where({"Time", name}) + ": only a dynamic run reads it, and Time/analysis is "
                            "static; set Time/analysis = dynamic or remove it");
    return;
  }
  if (dynamics.integrator != Integrator::generalizedAlpha && deck.given({"Time", "spectral radius"}))
    throw io::DeckError(deck.where({"Time", "spectral radius"}) + ": only generalized-alpha reads it, and "
                        "Time/integrator is " +
                        (dynamics.integrator == Integrator::backwardEuler ? std::string("backward Euler")
                                                                          : std::string("energy conserving")) +
                        "; remove it or set Time/integrator = generalized-alpha");
  const char *const names[3] = {"initial vx", "initial vy", "initial vz"};
  for (int c = 0; c < 3; ++c) {
    try {
      io::SpaceTimeExpression check(dynamics.initialVelocity[c]);
    } catch (const std::invalid_argument &e) {
      throw io::DeckError(deck.where({"Time", names[c]}) + ": " + e.what() +
                          " (an initial velocity is read at t = 0)");
    }
  }
}

double deckEndTime(const io::Deck &deck) {
  const double run = deck.root().sublist("Time").get<double>("end time");
  if (!deck.setOnCommandLine({"Time", "end time"})) return run;
  const Teuchos::ParameterEntry *file = deck.fileValue({"Time", "end time"});
  if (file == nullptr) return timeParameters().get<double>("end time");
  const Teuchos::any &value = file->getAny(false);
  if (value.type() != typeid(double)) return run;
  const double t = Teuchos::any_cast<double>(value);
  return std::isfinite(t) && t > 0.0 ? t : run;
}

} // namespace glossa::solvers
