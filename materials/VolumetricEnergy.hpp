#pragma once
// The volumetric energy U(theta) of the three-field functional (doc/theory.md, eq. 7), a function
// of the element dilatation theta. Its own small object so that the mixed element can evaluate
// it once per element and the augmented Lagrangian can swap kappa.

#include <string>

namespace glossa::materials {

class VolumetricEnergy {
public:
  enum class Form {
    SimoTaylor, // U = kappa/4 (theta^2 - 1 - 2 ln theta)   (deal.II step-44)
    LogSquared, // U = kappa/2 (ln theta)^2
    Quadratic   // U = kappa/2 (theta - 1)^2
  };

  VolumetricEnergy(Form form, double kappa);
  static Form formFromName(const std::string &name); // "simo-taylor", "log-squared", "quadratic"

  double energy(double theta) const;
  double dU(double theta) const;  // U'
  double d2U(double theta) const; // U''
  // The dilatation this law gives pressure p: the root of U'(theta) = p (1 for kappa = inf;
  // e for the log-squared law beyond the largest pressure it can carry, kappa / e).
  double dilatationAtPressure(double p) const;
  double kappa() const { return kappa_; }
  Form form() const { return form_; }
  VolumetricEnergy withKappa(double kappa) const { return {form_, kappa}; }

private:
  Form form_;
  double kappa_;
};

// Bulk modulus from shear modulus and Poisson's ratio: kappa = 2 mu (1 + nu) / (3 (1 - 2 nu)).
double bulkModulus(double mu, double nu);

} // namespace glossa::materials
