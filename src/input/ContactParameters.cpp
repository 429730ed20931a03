#include "input/ContactParameters.hpp"

#include <memory>
#include <stdexcept>

#include "contact/CylinderObstacle.hpp"
#include "contact/PlaneObstacle.hpp"
#include "contact/SphereObstacle.hpp"
#include "input/DeckSets.hpp"
#include "io/deck/DeckError.hpp"
#include "io/deck/ParameterSpec.hpp"

namespace glossa::input {

namespace {
using Teuchos::Array;
using Teuchos::ParameterList;

Eigen::Vector3d vec3(const Array<double> &a) { return {a[0], a[1], a[2]}; }

Array<double> unitZ() {
  Array<double> z(3, 0.0);
  z[2] = 1.0;
  return z;
}

// A parameter that must be given (> 0) for this contact: its declared default, 0, means not given
// (the schema's range already refuses a negative value). One not given is named at its sublist's
// line, the only line the deck has for it.
double positiveAt(const io::Deck &deck, const std::vector<std::string> &path, const std::string &why) {
  const ParameterList &list = deck.root().sublist(path[0]).sublist(path[1]);
  const double v = list.get<double>(path[2]);
  if (v > 0.0) return v;
  if (!deck.given(path))
    throw io::DeckError(deck.where({path[0], path[1]}) + ": no '" + path[2] + "' given; " + why +
                        " needs a value > 0");
  throw io::DeckError(deck.where(path) + " is 0; " + why + " needs a value > 0");
}

std::shared_ptr<const contact::Obstacle> buildObstacle(const io::Deck &deck, const std::string &name) {
  const ParameterList &c = deck.root().sublist("Contact").sublist(name);
  const std::string shape = c.get<std::string>("obstacle");
  const Eigen::Vector3d point = vec3(c.get<Array<double>>("point"));
  const contact::BodySide side =
      c.get<std::string>("body side") == "inside" ? contact::BodySide::inside : contact::BodySide::outside;
  const std::string vectorName = shape == "plane" ? "normal" : "axis";
  try {
    if (shape == "plane") return std::make_shared<contact::PlaneObstacle>(point, vec3(c.get<Array<double>>("normal")));
    const double radius = positiveAt(deck, {"Contact", name, "radius"}, "a " + shape);
    if (shape == "sphere") return std::make_shared<contact::SphereObstacle>(point, radius, side);
    return std::make_shared<contact::CylinderObstacle>(point, vec3(c.get<Array<double>>("axis")), radius, side);
  } catch (const std::invalid_argument &e) {
    // The constructors refuse a zero normal or axis (the radius is checked above).
    throw io::DeckError(deck.where({"Contact", name, vectorName}) + ": " + e.what());
  }
}
// The mean reference length of the faces' edges (each face's four, shared edges counted per
// face): the element size h of the default gap tolerance, 1e-3 h, a penetration far below what
// the elements resolve.
double meanEdgeLength(const mesh::HexMesh &m, const std::vector<mesh::ElementFace> &faces) {
  double sum = 0.0;
  for (const auto &face : faces)
    for (int k = 0; k < 4; ++k) {
      const auto &local = mesh::kHexFaceNodes[face.localFace];
      sum += (m.nodes[m.elements[face.element][local[k]]] - m.nodes[m.elements[face.element][local[(k + 1) % 4]]]).norm();
    }
  return faces.empty() ? 0.0 : sum / (4.0 * static_cast<double>(faces.size()));
}
}  // namespace

ParameterList contactParameters() {
  ParameterList p;
  io::declareString(p, "face set", "", "the body's faces that may touch the obstacle");
  io::declareString(p, "obstacle", "plane", "the rigid obstacle's shape", {"plane", "sphere", "cylinder"});
  io::declareDoubleArray(p, "point", Array<double>(3, 0.0), "m",
                         "plane: a point of it; sphere: its centre; cylinder: a point of its axis", 3);
  io::declareDoubleArray(p, "normal", unitZ(), "",
                         "plane: its normal, pointing to the body's side (made unit)", 3);
  io::declareDoubleArray(p, "axis", unitZ(), "", "cylinder: the direction of its axis", 3);
  io::declareDouble(p, "radius", 0.0, "m", "sphere, cylinder: the radius (required)", io::Range::nonNegative());
  io::declareString(p, "body side", "outside",
                    "sphere, cylinder: the body outside the obstacle (an indenter), or inside it (a cavity, a tube)",
                    {"outside", "inside"});
  io::declareDouble(p, "penalty", 0.0, "Pa/m",
                    "the penalty eps (required): contact pressure eps x penetration; a point pressed by p "
                    "penetrates p / eps",
                    io::Range::nonNegative());
  io::declareDouble(p, "search radius", 1.0, "m",
                    "contact points farther than this from the obstacle's surface, on either side, are not tested", io::Range::positive());
  io::declareString(p, "enforcement", "augmented Lagrangian",
                    "penalty: a point pressed by p penetrates p / eps; augmented Lagrangian: multipliers updated "
                    "in the Uzawa loop until the largest gap error is within the gap tolerance",
                    {"penalty", "augmented Lagrangian"});
  io::declareDouble(p, "gap tolerance", 0.0, "m",
                    "augmented Lagrangian: the largest gap error |g| of a point carrying pressure that ends the "
                    "Uzawa loop; 0: 1e-3 of the face set's mean edge length",
                    io::Range::nonNegative());
  io::declareString(p, "contact points", "gauss",
                    "where contact is tested on each face: its 2x2 Gauss points (consistent forces, the patch "
                    "test on any mesh) or its nodes (doc/contact.md)",
                    {"gauss", "nodal"});
  return p;
}

void buildContacts(const io::Deck &deck, const mesh::HexMesh &m, model::Scene &scene) {
  const ParameterList &contacts = deck.root().sublist("Contact");
  for (auto it = contacts.begin(); it != contacts.end(); ++it) {
    const std::string &name = contacts.name(it);
    const ParameterList &c = contacts.sublist(name);
    model::RigidContact contact;
    contact.name = name;
    contact.faces = faceSetAt(deck, m, {"Contact", name, "face set"});
    contact.obstacle = buildObstacle(deck, name);
    contact.settings.penalty = positiveAt(deck, {"Contact", name, "penalty"}, "the penalty method");
    contact.settings.searchRadius = c.get<double>("search radius");
    contact.settings.rule =
        c.get<std::string>("contact points") == "nodal" ? contact::ContactQuadrature::nodal : contact::ContactQuadrature::gauss;
    contact.enforcement = c.get<std::string>("enforcement") == "penalty" ? model::ContactEnforcement::penalty
                                                                          : model::ContactEnforcement::augmentedLagrangian;
    contact.gapTolerance = c.get<double>("gap tolerance");
    if (!(contact.gapTolerance > 0.0)) contact.gapTolerance = 1e-3 * meanEdgeLength(m, contact.faces);
    contact.state = std::make_shared<contact::ContactState>(contact.faces.size());
    scene.contacts.push_back(std::move(contact));
    // The contact tangent's area term is not symmetric: GMRES.
    scene.symmetricTangent = false;
  }
}

}  // namespace glossa::input
