#pragma once
// The channel the air flows through: its cross-sections in order from the nasal (upstream in
// inspiration) end to the tracheal end, each with its arc length along the centreline, its
// area, the wall's compliance there and whether the airway is closed there; and the air and
// separation constants of the flow model (doc/theory.md, "Airflow through the airway").

#include <vector>

namespace glossa::airflow {

struct ChannelSection {
  double arcLength = 0.0;   // along the centreline from the nasal end [m], increasing
  double area = 0.0;        // [m^2]; 0: closed
  double compliance = 0.0;  // dA/dp of the wall at the section [m^2/Pa]; 0: rigid
  bool closed = false;      // the walls touch across the whole section: no flow passes
};

struct AirSettings {
  double density = 1.2;           // [kg/m^3]
  double viscosity = 1.8e-5;      // dynamic [Pa s]; 0: inviscid
  double recoveryCoefficient = 0.0;  // share of Bernoulli's pressure change recovered past the throat, in [0, 1]
};

using Channel = std::vector<ChannelSection>;

}  // namespace glossa::airflow
