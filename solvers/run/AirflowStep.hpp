#pragma once
// What the coupling of the airflow and the solid reports of one step (doc/airflow.md): how it
// converged, and the flow at the converged state. No Trilinos.

#include <string>
#include <vector>

namespace glossa::solvers {

struct AirflowStep {
  bool on = false;                      // the scene has an airflow
  bool converged = false;
  std::string why;                      // not converged: why
  int iterations = 0;                   // coupling iterations (solid solves) of the step
  double residual = 0.0;                // the largest change of a section's pressure at the end [Pa]
  double flowRate = 0.0;                // [m^3/s]
  double nasalPressure = 0.0, trachealPressure = 0.0;  // [Pa]
  std::vector<double> sectionPressure;  // the pressures the solid was solved with, per lumen section [Pa]
  double smallestArea = 0.0;            // [m^2]
  int smallestSection = -1;
  bool closed = false, choked = false;
};

}  // namespace glossa::solvers
