#include "solvers/parameters/IncompressibilityParameters.hpp"

#include "io/deck/ParameterSpec.hpp"

namespace glossa::solvers {

Teuchos::ParameterList incompressibilityParameters() {
  Teuchos::ParameterList p;
  io::declareString(p, "method", "augmented Lagrangian",
                    "augmented Lagrangian: Uzawa updates of an element multiplier until every "
                    "element pressure obeys the material's volumetric law (Poisson's ratio or bulk "
                    "modulus; nu = 0.5: theta = 1), with the moderate kappa_t = kappa kappa_AL / "
                    "(kappa + kappa_AL) in the tangent; penalty: one solve with the material's "
                    "bulk modulus in the tangent (needs nu < 0.5); mixed: element pressures as "
                    "unknowns beside the displacements, no condensation and no Uzawa loop (any nu "
                    "up to 0.5), each Newton step a block solve by GMRES with a Teko block-triangular "
                    "preconditioner (MueLu on the displacement block, the scaled pressure mass "
                    "matrix for the Schur complement; needs Q1-P0)",
                    {"augmented Lagrangian", "penalty", "mixed"});
  io::declareDouble(p, "penalty ratio", 30.0, "",
                    "kappa_AL / mu in augmented-Lagrangian mode, mu the law's small-strain shear "
                    "modulus (30 keeps the Krylov total within about 2.4x of nu = 0.3 at every nu "
                    "and still needs about 2 Uzawa solves per step; 3 keeps the largest Krylov count "
                    "per solve within 2x across nu and mesh size, at about 3 Uzawa solves per step "
                    "for each of 30's; see doc/incompressibility.md)", io::Range::closed(1.0, 1e9));
  io::declareDouble(p, "dilatation tolerance", 1e-3, "",
                    "augmented Lagrangian stops when max_e |theta_e - theta_phys(p_e)| is below "
                    "this (theta_phys: the dilatation the material law gives the element pressure; "
                    "1 for nu = 0.5)",
                    io::Range::open(0.0, 1.0));
  io::declareInt(p, "maximum Uzawa iterations", 50, "Newton solves per step before the step fails",
                 io::Range::closed(1, 10000));
  io::declareString(p, "Uzawa acceleration", "inexact",
                    "none: every Newton solve to the full tolerance before a multiplier update (the "
                    "plain nested loop); inexact: the first solve of each step stops once its residual "
                    "is below 'inner tolerance' relative to the load, the multipliers are updated "
                    "there and Newton goes on from that iterate to the full tolerance "
                    "(doc/incompressibility.md)",
                    {"none", "inexact"});
  io::declareDouble(p, "inner tolerance", 1e-2, "",
                    "relative residual at which the first, inexact Uzawa solve of a step hands over "
                    "to the multiplier update", io::Range::open(0.0, 1.0));
  io::declareDouble(p, "inner linear tolerance", 1e-3, "",
                    "the largest relative tolerance of the Krylov solves inside that inexact solve "
                    "(Eisenstat-Walker may ask less): where it stops is where the multipliers are "
                    "updated, so its iterate must not depend on the linear solver; 1e-3 keeps 1 and 2 "
                    "ranks (iterative against direct) within 3e-7 of each other where the Newton "
                    "forcing's 1e-2 let them differ by 1.1e-5 (doc/incompressibility.md)",
                    io::Range::open(0.0, 1.0));
  io::declareString(p, "multiplier acceleration", "auto",
                    "augmented Lagrangian: none (each update sets the multipliers to beta p, the plain Uzawa "
                    "step), Anderson (each update combines it with the last 'Anderson depth' ones, Walker and "
                    "Ni 2011: the slow modes of active fibres are removed in a few updates) or auto (Anderson "
                    "under a controller, whose candidate solves may not raise kappa_AL, none elsewhere: the "
                    "supine gradient deck to 2.5 s takes 220 factorisations instead of 359, 0.62x the CPU "
                    "time; doc/incompressibility.md, 'Accelerating the multiplier update')",
                    {"auto", "none", "Anderson"});
  io::declareInt(p, "Anderson depth", 3, "multiplier acceleration = Anderson: the earlier updates combined",
                 io::Range::closed(1, 20));
  return p;
}

IncompressibilityParameters parseIncompressibilityParameters(const Teuchos::ParameterList &s) {
  IncompressibilityParameters p;
  const std::string method = s.get<std::string>("method");
  p.method = method == "mixed"     ? IncompressibilityMethod::mixed
             : method == "penalty" ? IncompressibilityMethod::penalty
                                   : IncompressibilityMethod::augmentedLagrangian;
  p.penaltyRatio = s.get<double>("penalty ratio");
  p.dilatationTolerance = s.get<double>("dilatation tolerance");
  p.maximumUzawaIterations = s.get<int>("maximum Uzawa iterations");
  p.inexactUzawa = s.get<std::string>("Uzawa acceleration") == "inexact";
  p.innerTolerance = s.get<double>("inner tolerance");
  p.innerLinearTolerance = s.get<double>("inner linear tolerance");
  const std::string acceleration = s.get<std::string>("multiplier acceleration");
  p.multiplierAcceleration = acceleration == "Anderson" ? MultiplierAcceleration::anderson
                             : acceleration == "none"   ? MultiplierAcceleration::none
                                                        : MultiplierAcceleration::automatic;
  p.andersonDepth = s.get<int>("Anderson depth");
  return p;
}

const char *methodName(IncompressibilityMethod method) {
  switch (method) {
  case IncompressibilityMethod::augmentedLagrangian: return "augmented Lagrangian";
  case IncompressibilityMethod::penalty: return "penalty";
  case IncompressibilityMethod::mixed: return "mixed";
  }
  return "";
}

} // namespace glossa::solvers
