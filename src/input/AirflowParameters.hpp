#pragma once
// The deck's "Airflow" section: the 1D airflow through the airway (doc/airflow.md) driven by the
// nasal and tracheal pressures or by the nasal pressure and a flow rate, each a value times a
// time function (a breath); the air's density and viscosity, the pressure recovery past the
// throat, how the sections' pressures map onto the faces, and the coupling's tolerance,
// relaxation and iteration limit. Declared and parsed into AirflowParameters; `driven by = off`
// (the default) turns the flow off, and then every other parameter given is refused.

#include <Teuchos_ParameterList.hpp>

#include "airflow/CouplingIteration.hpp"
#include "io/deck/Deck.hpp"
#include "model/TimeFunction.hpp"

namespace glossa::input {

Teuchos::ParameterList airflowParameters();

enum class AirflowDrive { off, pressures, flowRate };
enum class AirflowMapping { linear, nearestSection };
// Where the coupling iterates: one iteration per Newton solve inside the Uzawa loop, or one per
// converged step solve.
enum class AirflowLoop { uzawaLoop, stepSolve };

struct AirflowParameters {
  AirflowDrive drive = AirflowDrive::off;
  model::TimeFunction nasalPressure = model::TimeFunction::constant().scaled(0.0);     // [Pa]
  model::TimeFunction trachealPressure = model::TimeFunction::constant().scaled(0.0);  // [Pa], drive = pressures
  model::TimeFunction flowRate = model::TimeFunction::constant().scaled(0.0);          // [m^3/s], drive = flowRate
  double density = 1.2;              // [kg/m^3]
  double viscosity = 1.8e-5;         // [Pa s]
  double recoveryCoefficient = 0.0;  // past the throat, in [0, 1]
  AirflowMapping mapping = AirflowMapping::linear;
  double couplingTolerance = 0.1;    // [Pa]
  airflow::CouplingMethod couplingMethod = airflow::CouplingMethod::aitken;
  AirflowLoop loop = AirflowLoop::uzawaLoop;
  double relaxation = 0.5;           // the first iteration's, in (0, 1]
  int maximumCouplingIterations = 30;
};

// Whether the deck's Airflow section (validated, with its defaults) couples a flow inside the
// Uzawa loop: what the linear solver's defaults look at before the section is parsed.
bool airflowCoupledInUzawaLoop(const io::Deck &deck);

// `deck` validated against a schema holding airflowParameters() as "Airflow"; `endTime` the
// deck's own (a ramp's default duration). A parameter the drive does not read is a DeckError
// naming it.
AirflowParameters parseAirflowParameters(const io::Deck &deck, double endTime);

}  // namespace glossa::input
