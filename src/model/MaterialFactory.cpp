#include "model/MaterialFactory.hpp"

#include <limits>

#include "io/deck/DeckError.hpp"
#include "io/deck/ParameterSpec.hpp"
#include "materials/FibreReinforcedMaterial.hpp"
#include "materials/FungIsotropic.hpp"
#include "materials/NeoHookean.hpp"
#include "materials/ParallelElement.hpp"

namespace glossa::model {

using Teuchos::Array;
using Teuchos::ParameterList;

ParameterList materialParameters() {
  ParameterList p;
  io::declareString(p, "type", "neo-Hookean",
                    "isochoric matrix law: neo-Hookean (eq. 8, 'shear modulus') or Fung "
                    "A (exp(B (I1bar - 3)) - 1) (eq. 9 adipose, eq. 10 muscle matrix)",
                    {"neo-Hookean", "Fung"});
  io::declareDouble(p, "shear modulus", 80.194e6, "Pa", "mu of the neo-Hookean law", io::Range::positive());
  io::declareDouble(p, "Fung A", 1652.0, "Pa",
                    "Fung prefactor (muscle matrix c = 1.652 kPa, Table I; adipose A1 = 2500 Pa); see "
                    "doc/materials.md for the convention", io::Range::positive());
  io::declareDouble(p, "Fung B", 0.6265, "", "Fung exponent (muscle matrix b = 0.6265; adipose B1 = 2.75)",
                    io::Range::positive());
  io::declareDouble(p, "Poisson's ratio", 0.4999, "",
                    "nu, gives the bulk modulus kappa = 2 mu (1+nu) / (3 (1-2nu)) from the law's "
                    "small-strain shear modulus unless 'bulk modulus' is set; 0.5: exactly "
                    "incompressible (needs Incompressibility/method = augmented Lagrangian)",
                    {-1.0, 0.5, true, false});
  io::declareDouble(p, "bulk modulus", 0.0, "Pa", "kappa; 0 means: from Poisson's ratio",
                    io::Range::nonNegative());
  io::declareString(p, "volumetric energy", "simo-taylor",
                    "U(theta): simo-taylor kappa/4 (theta^2-1-2 ln theta) (as step-44), "
                    "log-squared kappa/2 ln^2 theta, quadratic kappa/2 (theta-1)^2",
                    {"simo-taylor", "log-squared", "quadratic"});
  io::declareString(p, "element", "Q1P0",
                    "Q1P0: three-field, pressure and dilatation condensed per element; Q1: plain "
                    "displacement element (locks; for comparison only)",
                    {"Q1P0", "Q1"});
  ParameterList &fibres = p.sublist("Fibre families", false,
                                    "passive fibre families reinforcing the matrix (rule of mixtures, "
                                    "eq. 3; tension only), one sublist each, constant direction");
  ParameterList &family = fibres.sublist(io::kAnySublist);
  io::declareDoubleArray(family, "direction", Array<double>(3, 0.0), "",
                         "reference fibre direction (normalised; must not be zero)", 3);
  ParameterList &law = p.sublist("Fibre law", false, "the passive fibre law and the mixture");
  io::declareDouble(law, "total fibre fraction", materials::kDefaultTotalFibreFraction, "",
                    "sum of the families' volume fractions, split equally (paper: 0.7)", io::Range::closed(0, 1));
  io::declareDouble(law, "T0max", materials::ParallelElement::kTableIT0max, "Pa",
                    "maximum isometric stress (Table I)", io::Range::positive());
  io::declareDouble(law, "parallel a", materials::ParallelElement::kTableIa, "",
                    "exponent coefficient of the parallel element (eq. 17)", io::Range::positive());
  io::declareDouble(law, "parallel A", materials::ParallelElement::kTableIA, "",
                    "amplitude of the parallel element, a fraction of T0max (eq. 17)", io::Range::positive());
  io::declareString(law, "stress form", "in-full",
                    "matrix stress with fibres: in-full (eq. 6, the paper's), fibre-direction-removed "
                    "(eq. 5; non-symmetric tangent, GMRES), mixture-weighted (eq. 2/4)",
                    {"in-full", "fibre-direction-removed", "mixture-weighted"});
  return p;
}

BuiltMaterial buildMaterial(const io::Deck &deck) {
  const ParameterList &mat = deck.root().sublist("Material");
  BuiltMaterial built;
  std::shared_ptr<const materials::IsochoricMaterial> matrix;
  if (mat.get<std::string>("type") == "Fung")
    matrix = std::make_shared<materials::FungIsotropic>(mat.get<double>("Fung A"), mat.get<double>("Fung B"));
  else
    matrix = std::make_shared<materials::NeoHookean>(mat.get<double>("shear modulus"));

  const ParameterList &fibres = mat.sublist("Fibre families");
  std::vector<Eigen::Vector3d> directions;
  for (auto it = fibres.begin(); it != fibres.end(); ++it) {
    const auto &d = fibres.sublist(fibres.name(it)).get<Array<double>>("direction");
    directions.emplace_back(d[0], d[1], d[2]);
    if (directions.back().norm() == 0.0)
      throw io::DeckError(deck.where({"Material", "Fibre families", fibres.name(it), "direction"}) +
                          " is zero; give the fibre direction");
  }
  if (directions.empty()) {
    built.isochoric = matrix;
  } else {
    const ParameterList &law = mat.sublist("Fibre law");
    const auto form = materials::matrixStressFormFromName(law.get<std::string>("stress form"));
    built.isochoric = std::make_shared<materials::FibreReinforcedMaterial>(
        matrix, materials::equalFractionFamilies(directions, law.get<double>("total fibre fraction")),
        std::make_shared<materials::ParallelElement>(law.get<double>("T0max"), law.get<double>("parallel a"),
                                                     law.get<double>("parallel A")),
        form);
    built.symmetricTangent = form != materials::MatrixStressForm::FibreDirectionRemoved;
  }

  const double mu = built.isochoric->shearModulus();
  const double kappaGiven = mat.get<double>("bulk modulus");
  const double nu = mat.get<double>("Poisson's ratio");
  // nu = 0.5 is exact incompressibility: an infinite bulk modulus, which the augmented Lagrangian
  // enforces as theta = 1 (solvers/AugmentedLagrangianRule).
  const double kappa = kappaGiven > 0.0 ? kappaGiven
                       : nu == 0.5      ? std::numeric_limits<double>::infinity()
                                        : materials::bulkModulus(mu, nu);
  built.volumetric = materials::VolumetricEnergy(
      materials::VolumetricEnergy::formFromName(mat.get<std::string>("volumetric energy")), kappa);
  built.plainQ1 = mat.get<std::string>("element") == "Q1";
  return built;
}

} // namespace glossa::model
