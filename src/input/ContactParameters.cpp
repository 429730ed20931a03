#include "input/ContactParameters.hpp"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>

#include "contact/CylinderObstacle.hpp"
#include "contact/DeformablePair.hpp"
#include "contact/MovingObstacle.hpp"
#include "contact/PlaneObstacle.hpp"
#include "contact/SphereObstacle.hpp"
#include "contact/SurfaceFile.hpp"
#include "contact/SurfaceOrientation.hpp"
#include "contact/TriangulatedObstacle.hpp"
#include "input/DeckSets.hpp"
#include "input/TimeFunctionParameters.hpp"
#include "input/UnreadParameters.hpp"
#include "input/DeckVector.hpp"
#include "io/deck/DeckError.hpp"
#include "io/deck/ParameterSpec.hpp"

namespace glossa::input {

namespace {
using Teuchos::Array;
using Teuchos::ParameterList;

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

// A triangulated surface from its file (relative to the deck), its normals turned to the body's
// side. The file's own errors (SurfaceError) name the file and line and pass through.
std::shared_ptr<const contact::Obstacle> buildSurface(const io::Deck &deck, const std::string &name) {
  const ParameterList &c = deck.root().sublist("Contact").sublist(name);
  const std::string file = c.get<std::string>("file");
  if (file.empty())
    throw io::DeckError(deck.where({"Contact", name}) + ": no 'file' given; a surface obstacle needs its OBJ or STL file");
  std::filesystem::path path(file);
  if (path.is_relative()) path = std::filesystem::path(deck.file()).parent_path() / path;
  const std::string normals = c.get<std::string>("normals");
  const contact::NormalSide side = normals == "outward"       ? contact::NormalSide::Outward
                                   : normals == "toward point" ? contact::NormalSide::TowardPoint
                                                               : contact::NormalSide::AsStored;
  contact::TriangleSurface surface = contact::readSurface(path.string(), c.get<double>("file unit"));
  const std::string fieldName = c.get<std::string>("normal field");
  const contact::NormalField field = fieldName == "smoothed"   ? contact::NormalField::smoothed
                                     : fieldName == "implicit" ? contact::NormalField::implicit
                                                               : contact::NormalField::faceted;
  return std::make_shared<contact::TriangulatedObstacle>(
      contact::orientNormals(std::move(surface), side, vec3(c.get<Array<double>>("body point"))), field,
      c.get<double>("smoothing radius"));
}

// The nodes of the contact's faces that start inside the obstacle deeper than the deck tolerates:
// refused, naming the deepest few, since the first Newton iteration would meet a pressure
// eps x depth that no load put there (doc/contact.md, "Overlaps at the start").
void checkStartingOverlap(const io::Deck &deck, const mesh::HexMesh &m, const model::RigidContact &contact) {
  const double tolerance = deck.root().sublist("Contact").sublist(contact.name).get<double>("start overlap tolerance");
  std::set<mesh::NodeId> nodes;
  for (const mesh::ElementFace &f : contact.faces)
    for (int a : mesh::kHexFaceNodes[f.localFace]) nodes.insert(m.elements[f.element][a]);
  std::vector<std::pair<double, mesh::NodeId>> inside;
  for (mesh::NodeId n : nodes) {
    const auto p = contact.obstacle->closest(m.nodes[n], contact.settings.searchRadius);
    if (p && p->gap < -tolerance) inside.emplace_back(p->gap, n);
  }
  if (inside.empty()) return;
  std::sort(inside.begin(), inside.end());
  std::ostringstream os;
  os << deck.where({"Contact", contact.name}) << ": " << inside.size()
     << " node(s) of face set '" << deck.root().sublist("Contact").sublist(contact.name).get<std::string>("face set")
     << "' start inside the obstacle deeper than 'start overlap tolerance' (" << tolerance << " m); deepest:";
  for (std::size_t k = 0; k < std::min<std::size_t>(inside.size(), 5); ++k)
    os << " node " << inside[k].second << " at " << -inside[k].first << " m";
  os << ". Move the obstacle, raise the tolerance, or leave those faces out of the face set";
  throw io::DeckError(os.str());
}

std::shared_ptr<const contact::Obstacle> buildObstacle(const io::Deck &deck, const std::string &name) {
  const ParameterList &c = deck.root().sublist("Contact").sublist(name);
  const std::string shape = c.get<std::string>("obstacle");
  if (shape == "surface") return buildSurface(deck, name);
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
// The obstacle's rigid motion, if the deck gives one (a translation or a rotation angle not 0):
// each translation component and the angle scaled by its own time function.
std::shared_ptr<contact::MovingObstacle> buildMotion(const io::Deck &deck, const std::string &name, double endTime,
                                                     std::shared_ptr<const contact::Obstacle> obstacle) {
  const ParameterList &c = deck.root().sublist("Contact").sublist(name);
  const Eigen::Vector3d translation = vec3(c.get<Array<double>>("translation"));
  const double angle = c.get<double>("rotation angle");
  if (translation.isZero(0.0) && angle == 0.0) return nullptr;
  std::array<contact::TimeFunctionOfT, 3> c_t;
  const char *axes[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    if (translation(k) == 0.0) continue;
    const model::TimeFunction f =
        timeFunctionAt(deck, {"Contact", name, std::string("translation ") + axes[k] + " time function"}, endTime);
    const double amplitude = translation(k);
    c_t[static_cast<std::size_t>(k)] = [f, amplitude](double t) { return amplitude * f(t); };
  }
  std::vector<contact::AxisRotation> rotations;
  if (angle != 0.0) {
    const model::TimeFunction f = timeFunctionAt(deck, {"Contact", name, "rotation time function"}, endTime);
    const Eigen::Vector3d axis = vec3(c.get<Array<double>>("rotation axis"));
    if (axis.isZero(0.0))
      throw io::DeckError(deck.where({"Contact", name, "rotation axis"}) + ": the axis is zero; a rotation needs a direction");
    rotations.push_back({axis, [f, angle](double t) { return angle * f(t); }});
  }
  return std::make_shared<contact::MovingObstacle>(
      std::move(obstacle), contact::RigidMotion(c_t, rotations, vec3(c.get<Array<double>>("pivot"))));
}

// Coulomb friction (coefficient 0: frictionless) or tied contact; the tangential penalty
// defaults to the normal one.
contact::FrictionSettings buildFriction(const io::Deck &deck, const std::string &name, double penalty) {
  const ParameterList &c = deck.root().sublist("Contact").sublist(name);
  refuseUnreadParameters(deck, {"Contact", name}, "friction",
                         {{"friction coefficient", {"Coulomb"}}, {"tangential penalty", {"Coulomb"}}});
  contact::FrictionSettings friction;
  friction.law = c.get<std::string>("friction") == "tied" ? contact::FrictionLaw::tied : contact::FrictionLaw::coulomb;
  friction.coefficient = c.get<double>("friction coefficient");
  const double epsT = c.get<double>("tangential penalty");
  friction.penalty = epsT > 0.0 ? epsT : penalty;
  return friction;
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

// A deformable pair (obstacle 'face set') or self-contact (obstacle 'self'): the master faces and
// each slave face's candidates in the reference configuration (contact/DeformablePair).
std::shared_ptr<const contact::DeformablePair> buildPair(const io::Deck &deck, const mesh::HexMesh &m,
                                                         const std::string &name,
                                                         const std::vector<mesh::ElementFace> &slave) {
  const ParameterList &c = deck.root().sublist("Contact").sublist(name);
  const bool self = c.get<std::string>("obstacle") == "self";
  const std::string rule = c.get<std::string>("contact points");
  if (rule == "nodal")
    throw io::DeckError(deck.where({"Contact", name, "contact points"}) +
                        ": 'nodal' on a pair of face sets; a pair's slave faces take 'gauss' (n x n, 'points per "
                        "direction') or 'segments'");
  std::vector<mesh::ElementFace> master = slave;
  if (!self) {
    const std::string masterSet = c.get<std::string>("master face set");
    if (masterSet.empty())
      throw io::DeckError(deck.where({"Contact", name}) +
                          ": obstacle 'face set' without a 'master face set'; name the face set the contact points "
                          "of 'face set' are searched against");
    if (masterSet == c.get<std::string>("face set"))
      throw io::DeckError(deck.where({"Contact", name, "master face set"}) + ": '" + masterSet +
                          "' is also the contact's 'face set'; a face set against itself is self-contact: set "
                          "obstacle = self");
    master = faceSetAt(deck, m, {"Contact", name, "master face set"});
  }
  double margin = c.get<double>("pairing margin");
  if (!(margin > 0.0)) margin = meanEdgeLength(m, slave);
  try {
    return std::make_shared<const contact::DeformablePair>(contact::pairFaces(
        m, slave, std::move(master), self, c.get<double>("search radius"), margin,
        rule == "segments" ? contact::SlaveRule::segments : contact::SlaveRule::gauss, c.get<int>("points per direction")));
  } catch (const std::invalid_argument &e) {
    throw io::DeckError(deck.where({"Contact", name, "master face set"}) + ": " + e.what());
  }
}

// Friction, tied contact and motion are built for rigid obstacles only: a pair that asks for them
// is refused rather than run frictionless and at rest.
void refuseRigidOnlyParameters(const io::Deck &deck, const std::string &name) {
  const ParameterList &c = deck.root().sublist("Contact").sublist(name);
  if (c.get<std::string>("friction") == "tied")
    throw io::DeckError(deck.where({"Contact", name, "friction"}) +
                        ": tied contact on a pair of face sets; it is built for rigid obstacles only: a pair is "
                        "frictionless (Coulomb with friction coefficient 0)");
  if (c.get<double>("friction coefficient") != 0.0)
    throw io::DeckError(deck.where({"Contact", name, "friction coefficient"}) +
                        ": friction on a pair of face sets; it is built for rigid obstacles only: allowed 0");
  if (!vec3(c.get<Array<double>>("translation")).isZero(0.0) || c.get<double>("rotation angle") != 0.0)
    throw io::DeckError(deck.where({"Contact", name}) +
                        ": a translation or rotation on a pair of face sets; only a rigid obstacle moves by the deck "
                        "(the faces of a pair move with the body)");
}
}  // namespace

ParameterList contactParameters() {
  ParameterList p;
  io::declareString(p, "face set", "", "the body's faces that may touch the obstacle (a pair's slave faces)");
  io::declareString(p, "obstacle", "plane",
                    "the rigid obstacle's shape, a triangulated surface read from a file, another face set of the "
                    "body ('master face set': a deformable pair) or the face set itself (self-contact)",
                    {"plane", "sphere", "cylinder", "surface", "face set", "self"});
  io::declareString(p, "master face set", "",
                    "obstacle 'face set': the faces the contact points of 'face set' are searched against");
  io::declareInt(p, "points per direction", 2,
                 "obstacle 'face set' or 'self': the n x n Gauss points of each slave face where contact is tested",
                 io::Range::closed(1, 8));
  io::declareDouble(p, "pairing margin", 0.0, "m",
                    "obstacle 'face set' or 'self': how much farther than the search radius, in the reference "
                    "configuration, a master face may be and still be paired with a slave face (the matrix "
                    "couples them); the run stops if the faces' displacements spread wider than this; 0: the "
                    "slave faces' mean edge length",
                    io::Range::nonNegative());
  io::declareString(p, "file", "", "surface: its Wavefront OBJ or STL (ASCII or binary) file, relative to the deck");
  io::declareDouble(p, "file unit", 1.0, "m", "surface: the length of one unit of the file's coordinates (1e-3 for mm)",
                    io::Range::positive());
  io::declareString(p, "normals", "as stored",
                    "surface: which way its normals point, i.e. the body's side: as the file winds them, "
                    "outward from the volume a closed surface encloses, or toward 'body point'",
                    {"as stored", "outward", "toward point"});
  io::declareString(p, "normal field", "faceted",
                    "surface: the contact normal, each triangle's own (faceted; it jumps from triangle to triangle) "
                    "or interpolated from the vertices' normals (smoothed: continuous across edges, for coarse "
                    "curved surfaces such as bones; doc/contact.md) or those of an implicit surface through the "
                    "vertices (implicit: the gap's gradient, and so the contact stiffness, continuous too, where "
                    "on the other two it turns by the angle between triangles; doc/contact.md)",
                    {"faceted", "smoothed", "implicit"});
  io::declareDouble(p, "smoothing radius", 0.0, "m",
                    "surface, normal field = implicit: the support radius R of the vertices' weights; 0: 2.5 mean "
                    "edge lengths of the surface. A surface of radius of curvature rho is smoothed inward by about "
                    "0.07 R^2 / rho",
                    io::Range::nonNegative());
  io::declareDoubleArray(p, "body point", Array<double>(3, 0.0), "m",
                         "surface with normals 'toward point': a point on the body's side of it", 3);
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
                    "where contact is tested on each face: its Gauss points (2x2; a pair's slave faces n x n, 'points "
                    "per direction'), its nodes (rigid obstacles), or, on a pair's slave faces, 6 points per "
                    "triangle of the cells the master faces' edges cut them into (segments: the patch test to "
                    "round-off on non-matching meshes; doc/contact.md)",
                    {"gauss", "nodal", "segments"});
  io::declareString(p, "friction", "Coulomb",
                    "Coulomb: regularised Coulomb friction, |t_T| <= mu t_N, with 'friction coefficient' mu "
                    "(0, the default: frictionless); tied: a point sticks, normally and tangentially, tension "
                    "allowed, to the obstacle's point where it first touched (doc/contact.md)",
                    {"Coulomb", "tied"});
  io::declareDouble(p, "friction coefficient", 0.0, "", "Coulomb: mu; 0 is frictionless", io::Range::nonNegative());
  io::declareDouble(p, "tangential penalty", 0.0, "Pa/m",
                    "Coulomb: eps_T, the sticking traction per unit of tangential slip since the last converged "
                    "step; 0: the penalty",
                    io::Range::nonNegative());
  io::declareDoubleArray(p, "translation", Array<double>(3, 0.0), "m",
                         "the obstacle's translation; each component times its own time function", 3);
  for (const char *axis : {"x", "y", "z"})
    p.set(std::string("translation ") + axis + " time function", timeFunctionParameters(),
          std::string("scales the translation's ") + axis + " component in time");
  io::declareDoubleArray(p, "rotation axis", unitZ(), "", "the axis of the obstacle's rotation (through 'pivot')", 3);
  io::declareDouble(p, "rotation angle", 0.0, "rad", "the obstacle's rotation angle, times the rotation time function");
  p.set("rotation time function", timeFunctionParameters(), "scales the rotation angle in time");
  io::declareDoubleArray(p, "pivot", Array<double>(3, 0.0), "m",
                         "the point the rotation turns about, in the obstacle's frame at rest", 3);
  io::declareDouble(p, "start overlap tolerance", 0.0, "m",
                    "how deep a node of the face set may start inside the obstacle; deeper is refused, naming the nodes",
                    io::Range::nonNegative());
  return p;
}

void buildContacts(const io::Deck &deck, const mesh::HexMesh &m, double endTime, model::Scene &scene) {
  const ParameterList &contacts = deck.root().sublist("Contact");
  for (auto it = contacts.begin(); it != contacts.end(); ++it) {
    const std::string &name = contacts.name(it);
    const ParameterList &c = contacts.sublist(name);
    model::RigidContact contact;
    contact.name = name;
    contact.faces = faceSetAt(deck, m, {"Contact", name, "face set"});
    const std::string shape = c.get<std::string>("obstacle");
    if (shape == "face set" || shape == "self") {
      contact.pair = buildPair(deck, m, name, contact.faces);
      refuseRigidOnlyParameters(deck, name);
    } else {
      contact.obstacle = buildObstacle(deck, name);
      contact.motion = buildMotion(deck, name, endTime, contact.obstacle);
      if (contact.motion) contact.obstacle = contact.motion;
    }
    contact.settings.penalty = positiveAt(deck, {"Contact", name, "penalty"}, "the penalty method");
    contact.settings.friction = buildFriction(deck, name, contact.settings.penalty);
    contact.settings.searchRadius = c.get<double>("search radius");
    if (!contact.pair && c.get<std::string>("contact points") == "segments")
      throw io::DeckError(deck.where({"Contact", name, "contact points"}) +
                          ": 'segments' against a rigid obstacle; segments are cut by a master face set's edges "
                          "(obstacle 'face set' or 'self'): use gauss or nodal");
    contact.settings.rule =
        c.get<std::string>("contact points") == "nodal" ? contact::ContactQuadrature::nodal : contact::ContactQuadrature::gauss;
    contact.enforcement = c.get<std::string>("enforcement") == "penalty" ? model::ContactEnforcement::penalty
                                                                          : model::ContactEnforcement::augmentedLagrangian;
    contact.gapTolerance = c.get<double>("gap tolerance");
    if (!(contact.gapTolerance > 0.0)) contact.gapTolerance = 1e-3 * meanEdgeLength(m, contact.faces);
    const std::size_t points = contact.pair ? contact.pair->pointsPerFace() : contact::ContactState::kPointsPerFace;
    contact.state = std::make_shared<contact::ContactState>(contact.faces.size(), points);
    if (contact.obstacle) checkStartingOverlap(deck, m, contact);
    scene.contacts.push_back(std::move(contact));
    // The contact tangent's area term is not symmetric: GMRES.
    scene.symmetricTangent = false;
  }
}

}  // namespace glossa::input
