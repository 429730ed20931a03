#include "input/MaterialFactory.hpp"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <map>
#include <tuple>

#include "input/DeckVector.hpp"
#include "io/deck/DeckError.hpp"
#include "io/deck/ParameterSpec.hpp"
#include "materials/ContractileCurveSets.hpp"
#include "materials/FungIsotropic.hpp"
#include "materials/HillMuscleFibre.hpp"
#include "materials/MooneyRivlin.hpp"
#include "materials/NeoHookean.hpp"
#include "materials/ParallelElement.hpp"
#include "materials/SeriesElement.hpp"
#include "materials/Yeoh.hpp"
#include "loads/ExternalMuscle.hpp"
#include "input/TimeFunctionParameters.hpp"
#include "input/DeckSets.hpp"
#include "input/MaterialParameterChecks.hpp"
#include "model/FibreDirectionField.hpp"

namespace glossa::input {

// The scene is the model layer's; this layer only reads it from the deck.
using namespace glossa::model;

using Teuchos::Array;
using Teuchos::ParameterList;

namespace {

ParameterList fibreFamilyParameters() {
  ParameterList family;
  io::declareString(family, "direction field", "constant",
                    "constant: 'direction' everywhere; radial fan: from 'fan centre' to each element's "
                    "centroid (in the plane normal to 'fan plane normal' if that is not zero); file: "
                    "vectors read from 'file'; polylines: the direction of the nearest segment of the "
                    "mesh's fibre polylines 'polylines' (to the centroid or to each quadrature point: "
                    "'polyline sampling')",
                    {"constant", "radial fan", "file", "polylines"});
  io::declareDoubleArray(family, "direction", Array<double>(3, 0.0), "",
                         "reference fibre direction (normalised; must not be zero)", 3);
  io::declareDoubleArray(family, "fan centre", Array<double>(3, 0.0), "m", "the point the fan radiates from", 3);
  io::declareDoubleArray(family, "fan plane normal", Array<double>(3, 0.0), "",
                         "normal of the plane the fan lies in; zero: a spherical fan", 3);
  io::declareString(family, "file", "",
                    "text file of lines 'id nx ny nz' (0-based ids, '#' comments), relative to the deck");
  io::declareString(family, "file gives", "element", "what the file's ids number", {"element", "node"});
  io::declareString(family, "polylines", "",
                    "polylines: the mesh's fibre polylines to follow (a muscle of Mesh/File/ANSYS fibres); "
                    "empty: those named like 'element set'");
  io::declareString(family, "polyline sampling", "element centroid",
                    "polylines: where the nearest segment is sought; element centroid: one direction per "
                    "element; quadrature points: one per Gauss point, so the direction varies inside an "
                    "element (doc/tongue.md measures the difference)",
                    {"element centroid", "quadrature points"});
  io::declareString(family, "element set", "", "elements the family is present in; empty: all");
  io::declareString(family, "muscle group", "",
                    "the muscle group (in 'Muscle groups') that activates the family; empty: passive fibres");
  return family;
}

ParameterList muscleGroupParameters() {
  ParameterList g;
  io::declareDouble(g, "T0s", 1.0, "", "scale of the contractile force (FFMR = T0s alpha)", io::Range::closed(0, 1));
  // The Hill elements of the group; 0 takes the Fibre law's value (Table I by default).
  for (const auto &[name, unit, doc] : {std::tuple{"T0max", "Pa", "maximum isometric stress"},
                                        {"parallel a", "", "exponent coefficient of the parallel element (eq. 17)"},
                                        {"parallel A", "", "amplitude of the parallel element (eq. 17)"},
                                        {"series c1", "", "amplitude of the series element (eq. 18)"},
                                        {"series c2", "", "exponent of the series element (eq. 18)"}})
    io::declareDouble(g, name, 0.0, unit, std::string(doc) + "; 0: the Fibre law's", io::Range::nonNegative());
  io::declareString(g, "curves", materials::defaultContractileCurveSet(),
                    "force-length and force-velocity curve set (doc/materials.md)",
                    {"physiological", "paper-table-II"});
  io::declareDouble(g, "rise time", 0.150, "s", "tau_R of the activation dynamics (eq. 24)", io::Range::positive());
  io::declareDouble(g, "fall time", 0.150, "s", "tau_F of the activation dynamics (eq. 24)", io::Range::positive());
  io::declareDouble(g, "minimum activation", 0.0, "", "alpha_min (eq. 24)", io::Range::closed(0, 0.999));
  io::declareDouble(g, "initial activation", 0.0, "", "alpha at t = 0, in [alpha_min, 1]", io::Range::closed(0, 1));
  io::declareDouble(g, "neural input scale", 1.0, "", "u(t) = scale x neural input(t), clamped to [0, 1]",
                    io::Range::closed(0, 1));
  g.set("neural input", timeFunctionParameters("constant"), "the neural input's time course");
  return g;
}

// One family as the deck gives it: where it is, which way it points, which group drives it.
struct FamilySpec {
  std::string name;
  int group = -1;
  std::vector<mesh::ElementId> elements;
  std::vector<Eigen::Vector3d> directions; // per entry of `elements`
  std::vector<PointDirections> pointDirections; // per entry of `elements`, or empty: constant in each element
};

FamilySpec readFamily(const io::Deck &deck, const mesh::HexMesh &m, const std::string &name,
                      const MuscleArchitecture &muscles) {
  const ParameterList &f = deck.root().sublist("Material").sublist("Fibre families").sublist(name);
  FamilySpec spec;
  spec.name = name;
  spec.elements = elementSetOrAll(deck, m, {"Material", "Fibre families", name, "element set"});
  spec.group = muscleGroupAt(deck, muscles, {"Material", "Fibre families", name, "muscle group"}, false);
  refuseOtherFieldsParameters(deck, {"Material", "Fibre families", name});
  const auto field = f.get<std::string>("direction field");
  try {
    if (field == "constant") {
      spec.directions = constantDirections(vec3(f.get<Array<double>>("direction")), spec.elements.size());
    } else if (field == "radial fan") {
      spec.directions = radialFanDirections(m, spec.elements, vec3(f.get<Array<double>>("fan centre")),
                                            vec3(f.get<Array<double>>("fan plane normal")));
    } else if (field == "polylines") {
      std::string lines = f.get<std::string>("polylines");
      if (lines.empty()) lines = f.get<std::string>("element set");
      const auto found = m.fibrePolylines.find(lines);
      if (found == m.fibrePolylines.end()) {
        std::string known;
        for (const auto &entry : m.fibrePolylines) known += (known.empty() ? "" : ", ") + entry.first;
        throw io::DeckError(deck.where({"Material", "Fibre families", name, "polylines"}) + ": no fibre polylines '" +
                            lines + "' in the mesh (" +
                            (known.empty() ? "it has none: give Mesh/File/ANSYS fibres" : "it has: " + known) + ")");
      }
      spec.directions = polylineDirections(m, spec.elements, found->second);
      if (f.get<std::string>("polyline sampling") == "quadrature points")
        spec.pointDirections = polylinePointDirections(m, spec.elements, found->second);
    } else {
      const auto file = f.get<std::string>("file");
      if (file.empty()) throw std::invalid_argument("'direction field' is file but 'file' is empty");
      std::filesystem::path p(file);
      if (p.is_relative()) p = std::filesystem::path(deck.file()).parent_path() / p;
      spec.directions = directionsFromFile(
          p, f.get<std::string>("file gives") == "node" ? DirectionsPer::Node : DirectionsPer::Element, m, spec.elements);
    }
  } catch (const io::DeckError &) {
    throw;
  } catch (const std::exception &e) {
    throw io::DeckError(deck.where({"Material", "Fibre families", name, field == "file" ? "file" : "direction field"}) +
                        ": " + e.what());
  }
  return spec;
}

// One family at a single material point (glossa point): every family acts there, pointing as its
// field gives at `x`; fields sampled from a mesh (polylines, file) and element sets are refused.
FamilySpec readPointFamily(const io::Deck &deck, const std::string &name, const MuscleArchitecture &muscles,
                           const Eigen::Vector3d &x) {
  const ParameterList &f = deck.root().sublist("Material").sublist("Fibre families").sublist(name);
  const std::vector<std::string> here{"Material", "Fibre families", name};
  auto at = [&](const char *parameter) {
    auto where = here;
    where.emplace_back(parameter);
    return where;
  };
  if (!f.get<std::string>("element set").empty())
    throw io::DeckError(deck.where(at("element set")) +
                        ": glossa point evaluates one material point, which lies in no element set; leave it empty");
  FamilySpec spec;
  spec.name = name;
  spec.elements = {0};
  spec.group = muscleGroupAt(deck, muscles, at("muscle group"), false);
  const auto field = f.get<std::string>("direction field");
  try {
    if (field == "constant")
      spec.directions = constantDirections(vec3(f.get<Array<double>>("direction")), 1);
    else if (field == "radial fan")
      spec.directions = {radialFanDirection(x, vec3(f.get<Array<double>>("fan centre")),
                                            vec3(f.get<Array<double>>("fan plane normal")))};
    else
      throw io::DeckError(deck.where(at("direction field")) + ": '" + field +
                          "' is sampled from a mesh; glossa point takes constant or radial fan");
  } catch (const std::invalid_argument &e) {
    throw io::DeckError(deck.where(at("direction field")) + ": " + e.what());
  }
  refuseOtherFieldsParameters(deck, here); // after the field itself, which glossa point may refuse
  return spec;
}

MuscleGroup readGroup(const io::Deck &deck, const std::string &name, double endTime) {
  const ParameterList &g = deck.root().sublist("Material").sublist("Muscle groups").sublist(name);
  MuscleGroup group;
  group.name = name;
  group.T0s = g.get<double>("T0s");
  materials::ActivationParameters a;
  a.tauR = g.get<double>("rise time");
  a.tauF = g.get<double>("fall time");
  a.alphaMin = g.get<double>("minimum activation");
  group.activation = materials::ActivationDynamics(a);
  group.initialActivation = g.get<double>("initial activation");
  if (group.initialActivation < a.alphaMin)
    throw io::DeckError(deck.where({"Material", "Muscle groups", name, "initial activation"}) + " = " +
                        std::to_string(group.initialActivation) + " is below the minimum activation " +
                        std::to_string(a.alphaMin));
  const ParameterList &input = g.sublist("neural input");
  for (double v : input.get<Array<double>>("values"))
    if (v < 0.0 || v > 1.0)
      throw io::DeckError(deck.where({"Material", "Muscle groups", name, "neural input", "values"}) +
                          ": a neural input must lie in [0, 1], got " + std::to_string(v));
  refuseUnreadTimeFunctionParameters(deck, {"Material", "Muscle groups", name, "neural input"});
  TimeFunction shape = TimeFunction::constant();
  try {
    shape = parseTimeFunction(input, endTime);
  } catch (const std::invalid_argument &e) {
    throw io::DeckError(deck.where({"Material", "Muscle groups", name, "neural input"}) + ": " + e.what());
  }
  const double scale = g.get<double>("neural input scale");
  group.input = shape.scaled(scale);
  return group;
}

// The Hill fibre of a muscle group: its own parameters where it sets them, else the Fibre law's;
// group -1: a passive fibre (a contractile element that never pulls).
materials::HillMuscleFibre hillFibre(const ParameterList &mat, const MuscleArchitecture &muscles, int group) {
  const ParameterList &law = mat.sublist("Fibre law");
  const ParameterList *g = group < 0 ? nullptr : &mat.sublist("Muscle groups").sublist(muscles.groups[group].name);
  auto value = [&](const char *name) {
    return g && g->get<double>(name) > 0.0 ? g->get<double>(name) : law.get<double>(name);
  };
  const double T0max = value("T0max");
  const materials::ParallelElement parallel(T0max, value("parallel a"), value("parallel A"));
  const materials::SeriesElement series(T0max, value("series c1"), value("series c2"));
  if (!g) return materials::HillMuscleFibre(parallel, series, materials::ContractileElement(T0max, 0.0, materials::physiologicalCurves()));
  return materials::HillMuscleFibre(parallel, series,
                                    materials::ContractileElement(T0max, muscles.groups[group].T0s,
                                                                  materials::contractileCurvesFromName(g->get<std::string>("curves"))));
}

ParameterList externalMuscleParameters() {
  ParameterList e;
  io::declareString(e, "muscle group", "", "the muscle group (in 'Muscle groups') that activates it");
  io::declareString(e, "insertion face set", "",
                    "faces whose nodes the fibres insert into, each node with its tributary area");
  io::declareString(e, "insertion node set", "",
                    "instead of a face set: nodes the fibres insert into, sharing 'cross-section area' equally "
                    "(a muscle entering the body through a few nodes, as the styloglossus does)");
  io::declareDouble(e, "cross-section area", 0.0, "m^2",
                    "with an insertion node set: the muscle's total fibre cross-section A (eq. 23)",
                    io::Range::nonNegative());
  io::declareString(e, "origin rule", "spacing",
                    "where each insertion node's fibre starts: spacing (eq. 26): P^O = P^I scaled by 'cs' "
                    "across 'axis' about the origin, moved by 'height' along 'axis'; fixed point: every "
                    "fibre starts at 'origin' (a bony anchor such as the styloid process)",
                    {"spacing", "fixed point"});
  io::declareDoubleArray(e, "origin", Teuchos::Array<double>(), "m", "fixed point: P^O (x, y, z)", 0);
  io::declareDouble(e, "cs", 1.0, "", "spacing rule: lateral scale of the origins (eq. 26)", io::Range::positive());
  io::declareDouble(e, "height", 2e-3, "m", "spacing rule: distance of the origins along 'axis' (eq. 26: h)");
  io::declareString(e, "axis", "y", "spacing rule: the direction the fibres run", {"x", "y", "z"});
  io::declareDouble(e, "fibre fraction", materials::kDefaultTotalFibreFraction, "",
                    "phi_f of the external portion (eq. 23; Table I: 0.7)", io::Range::open(0, 1.0000001));
  return e;
}

ExternalMuscleGroup readExternalMuscle(const io::Deck &deck, const mesh::HexMesh &m, const std::string &name,
                                       const MuscleArchitecture &muscles) {
  const ParameterList &mat = deck.root().sublist("Material");
  const ParameterList &e = mat.sublist("External muscles").sublist(name);
  ExternalMuscleGroup out;
  out.name = name;
  out.group = muscleGroupAt(deck, muscles, {"Material", "External muscles", name, "muscle group"}, true);
  const std::vector<std::string> here{"Material", "External muscles", name};
  auto at = [&](const char *parameter) {
    auto path = here;
    path.emplace_back(parameter);
    return path;
  };
  const bool byFaces = !e.get<std::string>("insertion face set").empty();
  const bool byNodes = !e.get<std::string>("insertion node set").empty();
  if (byFaces == byNodes)
    throw io::DeckError(deck.where(here) + ": give either 'insertion face set' or 'insertion node set'");
  std::map<mesh::NodeId, double> areas;
  if (byFaces) {
    std::vector<std::array<std::int64_t, 4>> faces;
    for (const auto &f : faceSetAt(deck, m, at("insertion face set"))) {
      std::array<std::int64_t, 4> nodes{};
      for (int k = 0; k < 4; ++k) nodes[k] = m.elements[f.element][mesh::kHexFaceNodes[f.localFace][k]];
      faces.push_back(nodes);
    }
    for (const auto &[node, area] : loads::tributaryAreas(faces, m.nodes)) areas[node] = area;
  } else {
    const auto &nodes = nodeSetAt(deck, m, at("insertion node set"));
    const double total = e.get<double>("cross-section area");
    if (!(total > 0.0))
      throw io::DeckError(deck.where(at("cross-section area")) + " must be > 0 with an insertion node set");
    for (const auto node : nodes) areas[node] = total / static_cast<double>(nodes.size());
  }
  const bool fixedPoint = e.get<std::string>("origin rule") == "fixed point";
  const auto &origin = e.get<Teuchos::Array<double>>("origin");
  if (fixedPoint && origin.size() != 3)
    throw io::DeckError(deck.where(at("origin")) + ": the fixed point needs 3 coordinates, got " +
                        std::to_string(origin.size()));
  const int axis = e.get<std::string>("axis")[0] - 'x';
  for (const auto &[node, area] : areas) {
    loads::ExternalFibre fibre;
    fibre.insertion = m.nodes[node];
    fibre.origin = fixedPoint ? Eigen::Vector3d(origin[0], origin[1], origin[2])
                              : loads::spacingRuleOrigin(fibre.insertion, e.get<double>("cs"), e.get<double>("height"), axis);
    if (!((fibre.origin - fibre.insertion).norm() > 0.0))
      throw io::DeckError(deck.where(at("origin")) + ": the origin coincides with insertion node " + std::to_string(node));
    fibre.area = area;
    out.nodes.push_back(node);
    out.fibres.push_back(fibre);
  }
  out.law = std::make_shared<loads::ExternalMuscle>(hillFibre(mat, muscles, out.group), e.get<double>("fibre fraction"));
  return out;
}

// The matrix law of a tissue, its volumetric law and density: declared alike for the Material
// section (the law of every element in no tissue's set) and for each sublist of Material/Tissues.
void declareMatrixLaw(ParameterList &p) {
  io::declareString(p, "type", "neo-Hookean",
                    "isochoric matrix law: neo-Hookean (eq. 8, 'shear modulus'); Fung "
                    "A (exp(B (I1bar - 3)) - 1) (eq. 9 adipose, eq. 10 muscle matrix); Mooney-Rivlin "
                    "C10 (I1bar-3) + C01 (I2bar-3) + C11 (I1bar-3)(I2bar-3) + C20 (I1bar-3)^2 + C02 (I2bar-3)^2 "
                    "(C10 and C01 alone: the two-parameter law; C10 = 1037, C20 = 486 Pa: the ArtiSynth "
                    "tongue's); Yeoh C10 (I1bar-3) + C20 (I1bar-3)^2 + C30 (I1bar-3)^3",
                    {"neo-Hookean", "Fung", "Mooney-Rivlin", "Yeoh"});
  io::declareDouble(p, "shear modulus", 80.194e6, "Pa", "mu of the neo-Hookean law", io::Range::positive());
  io::declareDouble(p, "Fung A", 1652.0, "Pa",
                    "Fung prefactor (muscle matrix c = 1.652 kPa, Table I; adipose A1 = 2500 Pa); see "
                    "doc/materials.md for the convention", io::Range::positive());
  io::declareDouble(p, "Fung B", 0.6265, "", "Fung exponent (muscle matrix b = 0.6265; adipose B1 = 2.75)",
                    io::Range::positive());
  io::declareDouble(p, "C10", 1037.0, "Pa",
                    "Mooney-Rivlin and Yeoh: coefficient of (I1bar - 3) (the ArtiSynth tongue: 1037 Pa)");
  for (const auto &[name, doc] :
       {std::pair{"C01", "Mooney-Rivlin: coefficient of (I2bar - 3)"},
        {"C11", "Mooney-Rivlin: coefficient of (I1bar - 3)(I2bar - 3)"},
        {"C20", "Mooney-Rivlin and Yeoh: coefficient of (I1bar - 3)^2 (the ArtiSynth tongue: 486 Pa)"},
        {"C02", "Mooney-Rivlin: coefficient of (I2bar - 3)^2"},
        {"C30", "Yeoh: coefficient of (I1bar - 3)^3"}})
    io::declareDouble(p, name, 0.0, "Pa", doc);
  io::declareDouble(p, "Poisson's ratio", 0.4999, "",
                    "nu, gives the bulk modulus kappa = 2 mu (1+nu) / (3 (1-2nu)) from the law's "
                    "small-strain shear modulus unless 'bulk modulus' is set; 0.5: exactly "
                    "incompressible (needs Incompressibility/method = augmented Lagrangian or mixed)",
                    {-1.0, 0.5, true, false});
  io::declareDouble(p, "bulk modulus", 0.0, "Pa", "kappa; 0 means: from Poisson's ratio",
                    io::Range::nonNegative());
  io::declareString(p, "volumetric energy", "simo-taylor",
                    "U(theta): simo-taylor kappa/4 (theta^2-1-2 ln theta) (as step-44), "
                    "log-squared kappa/2 ln^2 theta, quadratic kappa/2 (theta-1)^2",
                    {"simo-taylor", "log-squared", "quadratic"});
  io::declareDouble(p, "density", 1060.0, "kg/m^3",
                    "mass density for body forces (muscle 1060, adipose 920, cartilage 1000, bone 1900)",
                    io::Range::positive());
}

// One tissue as the deck gives it at `path` (the Material section or a Tissues sublist).
Tissue buildTissue(const io::Deck &deck, const std::vector<std::string> &path, const ParameterList &t,
                   const std::string &name) {
  auto at = [&](const char *parameter) {
    auto where = path;
    where.emplace_back(parameter);
    return deck.where(where);
  };
  Tissue tissue;
  tissue.name = name;
  const auto type = t.get<std::string>("type");
  refuseOtherLawsParameters(deck, path);
  try {
    if (type == "Fung") {
      tissue.matrix = std::make_shared<materials::FungIsotropic>(t.get<double>("Fung A"), t.get<double>("Fung B"));
    } else if (type == "Mooney-Rivlin") {
      materials::MooneyRivlinParameters c;
      c.C10 = t.get<double>("C10");
      c.C01 = t.get<double>("C01");
      c.C11 = t.get<double>("C11");
      c.C20 = t.get<double>("C20");
      c.C02 = t.get<double>("C02");
      tissue.matrix = std::make_shared<materials::MooneyRivlin>(c);
    } else if (type == "Yeoh") {
      tissue.matrix = std::make_shared<materials::Yeoh>(t.get<double>("C10"), t.get<double>("C20"), t.get<double>("C30"));
    } else {
      tissue.matrix = std::make_shared<materials::NeoHookean>(t.get<double>("shear modulus"));
    }
  } catch (const std::invalid_argument &e) {
    throw io::DeckError(at("type") + " = " + type + ": " + e.what());
  }
  tissue.density = t.get<double>("density");
  const double mu = tissue.matrix->shearModulus();
  const double nu = t.get<double>("Poisson's ratio");
  // nu = 0.5 is exact incompressibility: an infinite bulk modulus, which the augmented Lagrangian
  // enforces as theta = 1 (solvers/incompressibility/AugmentedLagrangianRule).
  const double kappa = bulkModulusGiven(deck, path) ? t.get<double>("bulk modulus")
                       : nu == 0.5      ? std::numeric_limits<double>::infinity()
                                        : materials::bulkModulus(mu, nu);
  tissue.volumetric = materials::VolumetricEnergy(
      materials::VolumetricEnergy::formFromName(t.get<std::string>("volumetric energy")), kappa);
  return tissue;
}

ParameterList tissueParameters() {
  ParameterList t;
  io::declareString(t, "element set", "", "the elements of this tissue (required; an element is in one tissue at most)");
  declareMatrixLaw(t);
  return t;
}

// Per element (of `numElements`): the families present, in deck order, their directions, and the
// region (tissue and families) whose point law they share (eq. 14's rule of mixtures: the
// total fibre fraction divided evenly among the families present).
void assignFibreRegions(const io::Deck &deck, const std::vector<FamilySpec> &families, std::size_t numElements,
                        BuiltMaterial &built) {
  const ParameterList &mat = deck.root().sublist("Material");
  MuscleArchitecture &muscles = built.muscles;
  const ParameterList &law = mat.sublist("Fibre law");
  const auto form = materials::matrixStressFormFromName(law.get<std::string>("stress form"));
  built.symmetricTangent = families.empty() || form != materials::MatrixStressForm::FibreDirectionRemoved;
  if (!families.empty()) {
    // Per element: the families present (in deck order) and their directions.
    std::vector<std::vector<int>> present(numElements);
    std::vector<std::vector<Eigen::Vector3d>> directions(numElements);
    std::vector<std::vector<PointDirections>> pointDirections(numElements);
    const bool perPoint = std::any_of(families.begin(), families.end(),
                                      [](const FamilySpec &f) { return !f.pointDirections.empty(); });
    for (std::size_t f = 0; f < families.size(); ++f)
      for (std::size_t k = 0; k < families[f].elements.size(); ++k) {
        const auto e = static_cast<std::size_t>(families[f].elements[k]);
        present[e].push_back(static_cast<int>(f));
        directions[e].push_back(families[f].directions[k]);
        if (!perPoint) continue;
        PointDirections N;
        if (families[f].pointDirections.empty())
          N.fill(families[f].directions[k]);
        else
          N = families[f].pointDirections[k];
        pointDirections[e].push_back(N);
      }
    const double total = law.get<double>("total fibre fraction");
    auto hill = [&](int group) { return hillFibre(mat, muscles, group); };
    // A region: the families present and the tissue whose matrix they reinforce.
    std::map<std::pair<int, std::vector<int>>, int> regionOf;
    muscles.elementRegion.assign(numElements, -1);
    muscles.directions.resize(numElements);
    if (perPoint) muscles.pointDirections.resize(numElements);
    for (std::size_t e = 0; e < numElements; ++e) {
      if (present[e].empty()) continue;
      // The point law holds a fixed number of families; the deck may declare more, as long as
      // no element carries more than that many (the tongue: 21 bundles, at most 3 per element).
      if (present[e].size() > static_cast<std::size_t>(materials::kMaxFibreFamilies)) {
        std::string names;
        for (int f : present[e]) names += (names.empty() ? "" : ", ") + families[f].name;
        throw io::DeckError(deck.where({"Material", "Fibre families"}) + ": element " + std::to_string(e) + " carries " +
                            std::to_string(present[e].size()) + " fibre families (" + names + "); at most " +
                            std::to_string(materials::kMaxFibreFamilies) + " per element");
      }
      const int tissue = built.elementTissue[e];
      auto [it, inserted] = regionOf.emplace(std::pair{tissue, present[e]}, static_cast<int>(muscles.regions.size()));
      if (inserted) {
        FibreRegion region;
        std::vector<materials::MuscleMaterial::Family> laws;
        const double phi = total / static_cast<double>(present[e].size());
        for (int f : present[e]) {
          laws.push_back({materials::FibreFamily{Eigen::Vector3d::UnitX(), phi}, hill(families[f].group)});
          region.familyGroup.push_back(families[f].group);
          region.familyNames.push_back(families[f].name);
        }
        region.law = std::make_shared<materials::MuscleMaterial>(built.tissues[tissue].matrix, std::move(laws), form);
        muscles.regions.push_back(std::move(region));
      }
      muscles.elementRegion[e] = it->second;
      materials::FamilyDirections N(3, static_cast<Eigen::Index>(present[e].size()));
      for (std::size_t k = 0; k < present[e].size(); ++k) N.col(static_cast<Eigen::Index>(k)) = directions[e][k];
      muscles.directions[e] = N;
      if (perPoint)
        for (std::size_t q = 0; q < 8; ++q) {
          materials::FamilyDirections Nq(3, static_cast<Eigen::Index>(present[e].size()));
          for (std::size_t k = 0; k < present[e].size(); ++k) Nq.col(static_cast<Eigen::Index>(k)) = pointDirections[e][k][q];
          muscles.pointDirections[e][q] = Nq;
        }
    }
  }

}

} // namespace

ParameterList materialParameters() {
  ParameterList p;
  declareMatrixLaw(p);
  ParameterList tissues;
  tissues.set(io::kAnySublist, tissueParameters(), "one tissue");
  p.set("Tissues", tissues,
        "further tissues, one sublist each: an element set with its own matrix law, volumetric law and "
        "density (bone, cartilage, adipose tissue beside muscle); elements in none have the Material "
        "section's own law");
  io::declareString(p, "element", "Q1P0",
                    "Q1P0: three-field, pressure and dilatation condensed per element; Q1: plain "
                    "displacement element (locks; for comparison only)",
                    {"Q1P0", "Q1"});
  ParameterList &fibres = p.sublist("Fibre families", false,
                                    "fibre families reinforcing the matrix (rule of mixtures, eq. 3; tension "
                                    "only), one sublist each; active when a muscle group drives them");
  fibres.set(io::kAnySublist, fibreFamilyParameters(), "one fibre family");
  ParameterList groups;
  groups.set(io::kAnySublist, muscleGroupParameters(), "one muscle group");
  p.set("Muscle groups", groups, "muscle groups: activation dynamics and neural input, one sublist each");
  ParameterList external;
  external.set(io::kAnySublist, externalMuscleParameters(), "one external muscle");
  p.set("External muscles", external,
        "muscles outside the mesh (eq. 22-23): fibres from fixed origins pulling on the nodes of a face set");
  ParameterList &law = p.sublist("Fibre law", false, "the Hill fibre (eq. 11-18) and the mixture");
  io::declareDouble(law, "total fibre fraction", materials::kDefaultTotalFibreFraction, "",
                    "sum of the volume fractions of the families present at a point, split equally (paper: 0.7)",
                    io::Range::closed(0, 1));
  io::declareDouble(law, "T0max", materials::ParallelElement::kTableIT0max, "Pa",
                    "maximum isometric stress (Table I)", io::Range::positive());
  io::declareDouble(law, "parallel a", materials::ParallelElement::kTableIa, "",
                    "exponent coefficient of the parallel element (eq. 17)", io::Range::positive());
  io::declareDouble(law, "parallel A", materials::ParallelElement::kTableIA, "",
                    "amplitude of the parallel element, a fraction of T0max (eq. 17)", io::Range::positive());
  io::declareDouble(law, "series c1", materials::SeriesElement::kTableIc1, "",
                    "amplitude of the series element, a fraction of T0max (eq. 18)", io::Range::positive());
  io::declareDouble(law, "series c2", materials::SeriesElement::kTableIc2, "",
                    "exponent of the series element (eq. 18)", io::Range::positive());
  io::declareString(law, "stress form", "in-full",
                    "matrix stress with fibres: in-full (eq. 6, the paper's), fibre-direction-removed "
                    "(eq. 5; non-symmetric tangent, GMRES), mixture-weighted (eq. 2/4)",
                    {"in-full", "fibre-direction-removed", "mixture-weighted"});
  return p;
}

BuiltMaterial buildMaterial(const io::Deck &deck, const mesh::HexMesh &m, double endTime) {
  const ParameterList &mat = deck.root().sublist("Material");
  BuiltMaterial built;
  built.tissues.push_back(buildTissue(deck, {"Material"}, mat, "Material"));
  built.elementTissue.assign(m.numElements(), 0);
  const ParameterList &tissues = mat.sublist("Tissues");
  for (auto it = tissues.begin(); it != tissues.end(); ++it) {
    const std::string &name = tissues.name(it);
    const std::vector<std::string> path{"Material", "Tissues", name};
    const int index = static_cast<int>(built.tissues.size());
    built.tissues.push_back(buildTissue(deck, path, tissues.sublist(name), name));
    if (tissues.sublist(name).get<std::string>("element set").empty())
      throw io::DeckError(deck.where({"Material", "Tissues", name, "element set"}) + " is empty: name the tissue's elements");
    for (const auto e : elementSetOrAll(deck, m, {"Material", "Tissues", name, "element set"})) {
      int &owner = built.elementTissue[static_cast<std::size_t>(e)];
      if (owner != 0)
        throw io::DeckError(deck.where({"Material", "Tissues", name, "element set"}) + ": element " + std::to_string(e) +
                            " is already in tissue '" + built.tissues[owner].name + "'; an element has one tissue");
      owner = index;
    }
  }

  MuscleArchitecture &muscles = built.muscles;
  const ParameterList &groups = mat.sublist("Muscle groups");
  for (auto it = groups.begin(); it != groups.end(); ++it) muscles.groups.push_back(readGroup(deck, groups.name(it), endTime));

  const ParameterList &fibres = mat.sublist("Fibre families");
  std::vector<FamilySpec> families;
  for (auto it = fibres.begin(); it != fibres.end(); ++it) families.push_back(readFamily(deck, m, fibres.name(it), muscles));

  const ParameterList &externals = mat.sublist("External muscles");
  for (auto it = externals.begin(); it != externals.end(); ++it)
    muscles.external.push_back(readExternalMuscle(deck, m, externals.name(it), muscles));

  assignFibreRegions(deck, families, m.numElements(), built);
  built.plainQ1 = mat.get<std::string>("element") == "Q1";
  return built;
}

BuiltMaterial buildPointMaterial(const io::Deck &deck, const Eigen::Vector3d &x, double endTime) {
  const ParameterList &mat = deck.root().sublist("Material");
  for (const char *section : {"Tissues", "External muscles"})
    if (mat.sublist(section).numParams() > 0)
      throw io::DeckError(deck.where({"Material", section}) +
                          ": glossa point evaluates the Material section's own law at one point; " +
                          "leave this section empty");
  BuiltMaterial built;
  built.tissues.push_back(buildTissue(deck, {"Material"}, mat, "Material"));
  built.elementTissue.assign(1, 0);
  MuscleArchitecture &muscles = built.muscles;
  const ParameterList &groups = mat.sublist("Muscle groups");
  for (auto it = groups.begin(); it != groups.end(); ++it) muscles.groups.push_back(readGroup(deck, groups.name(it), endTime));
  const ParameterList &fibres = mat.sublist("Fibre families");
  std::vector<FamilySpec> families;
  for (auto it = fibres.begin(); it != fibres.end(); ++it)
    families.push_back(readPointFamily(deck, fibres.name(it), muscles, x));
  assignFibreRegions(deck, families, 1, built);
  return built;
}

} // namespace glossa::input
