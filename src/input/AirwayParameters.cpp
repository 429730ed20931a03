#include "input/AirwayParameters.hpp"

#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>

#include "contact/SurfaceFile.hpp"
#include "input/DeckSets.hpp"
#include "input/DeckVector.hpp"
#include "io/deck/DeckError.hpp"
#include "io/deck/ParameterSpec.hpp"

namespace glossa::input {

namespace {
using Teuchos::Array;
using Teuchos::ParameterList;

Array<double> unitY() {
  Array<double> y(3, 0.0);
  y[1] = 1.0;
  return y;
}

// A parameter the airway cannot do without, named at the section's line when not given.
void require(const io::Deck &deck, const std::string &name, const std::string &why) {
  if (!deck.given({"Airway", name}))
    throw io::DeckError(deck.where({"Airway"}) + ": no '" + name + "' given; the airway needs " + why);
}

// The face set's faces as triangles of their own vertex list (each quadrilateral split along the
// diagonal from its first corner), at the imaged positions, and the vertices' mesh nodes.
airway::TriangleSet tongueTriangles(const mesh::HexMesh &m, const std::vector<mesh::ElementFace> &faces,
                                    std::vector<mesh::NodeId> &nodes) {
  airway::TriangleSet set;
  std::map<mesh::NodeId, int> vertexOf;
  auto vertex = [&](mesh::NodeId n) {
    const auto [it, added] = vertexOf.try_emplace(n, static_cast<int>(nodes.size()));
    if (added) {
      nodes.push_back(n);
      set.vertices.push_back(m.imagedPosition(n));
    }
    return it->second;
  };
  for (const mesh::ElementFace &f : faces) {
    std::array<int, 4> q;
    for (int k = 0; k < 4; ++k)
      q[static_cast<std::size_t>(k)] = vertex(m.elements[f.element][mesh::kHexFaceNodes[f.localFace][static_cast<std::size_t>(k)]]);
    set.triangles.push_back({q[0], q[1], q[2]});
    set.triangles.push_back({q[0], q[2], q[3]});
  }
  return set;
}

airway::TriangleSet wallTriangles(const io::Deck &deck) {
  const ParameterList &a = deck.root().sublist("Airway");
  std::filesystem::path path(a.get<std::string>("wall file"));
  if (path.is_relative()) path = std::filesystem::path(deck.file()).parent_path() / path;
  const contact::TriangleSurface surface = contact::readSurface(path.string(), a.get<double>("wall file unit"));
  return {surface.vertices(), surface.triangles()};
}

// The index of the item (a contact, a load: `what`, of the deck's `section`) the Airway parameter
// `parameter` names among `items`; -1 when it names none; a name not among them is refused with the
// names there are.
template <class Item>
int namedIndex(const io::Deck &deck, const std::string &parameter, const std::vector<Item> &items,
               const std::string &what, const std::string &section) {
  const std::string name = deck.root().sublist("Airway").get<std::string>(parameter);
  if (name.empty()) return -1;
  std::string known;
  for (std::size_t k = 0; k < items.size(); ++k) {
    if (items[k].name == name) return static_cast<int>(k);
    known += (known.empty() ? "" : ", ") + items[k].name;
  }
  throw io::DeckError(deck.where({"Airway", parameter}) + ": no " + what + " '" + name + "' in the " + section +
                      " section (" + (known.empty() ? std::string("it has none") : "it has: " + known) + ")");
}
}  // namespace

ParameterList airwayParameters() {
  ParameterList p;
  io::declareString(p, "face set", "",
                    "the tongue's faces that bound the airway (e.g. 'airway'); empty: no airway output");
  io::declareString(p, "wall file", "",
                    "the rigid wall across the airway (palate, velum, pharyngeal wall): an OBJ or STL file, "
                    "relative to the deck");
  io::declareDouble(p, "wall file unit", 1.0, "m", "the length of one unit of the wall file's coordinates",
                    io::Range::positive());
  io::declareInt(p, "sections", 20, "the number of cross-sections, at equal steps along the centreline",
                 io::Range::closed(1, 500));
  io::declareDoubleArray(p, "start point", Array<double>(3, 0.0), "m",
                         "the centreline starts on the tongue's midsagittal airway curve nearest this point "
                         "(e.g. under the velum; required)", 3);
  io::declareDoubleArray(p, "end point", Array<double>(3, 0.0), "m",
                         "the centreline ends on that curve nearest this point (e.g. at the vallecula; required)", 3);
  io::declareDoubleArray(p, "midsagittal point", Array<double>(3, 0.0), "m", "a point of the midsagittal plane", 3);
  io::declareDoubleArray(p, "lateral axis", unitY(), "",
                         "the midsagittal plane's normal: the sections' lateral direction", 3);
  io::declareDouble(p, "closing area", 1e-6, "m^2", "a section whose area is below this is closed",
                    io::Range::nonNegative());
  io::declareDouble(p, "contact gap", 1e-5, "m",
                    "a section where the tongue is within this of the wall across the closing width fraction of "
                    "its width is closed",
                    io::Range::nonNegative());
  io::declareDouble(p, "closing width fraction", 1.0, "",
                    "the fraction of a section's width the tongue must be within the contact gap of the wall over "
                    "for the section to close (1: the whole width, side to side)",
                    io::Range{0.0, 1.0, true, false});
  io::declareDouble(p, "lateral half-width", 0.0, "m",
                    "the lateral pharyngeal walls: planes this far either side of the midsagittal plane that bound "
                    "every section's width (a measuring bound, not a contact obstacle); 0: none, the narrower of "
                    "the tongue's airway faces and the wall sets the width (doc/airway.md)",
                    io::Range::nonNegative());
  io::declareString(p, "contact", "",
                    "the contact (a Contact sublist) whose area airway.csv reports as the tongue-wall contact area");
  io::declareString(p, "closing pressure load", "",
                    "a follower pressure (a Loads sublist) on the airway whose suction the run raises until the "
                    "airway closes, then bisects to the closing pressure Pcrit; empty: no search");
  io::declareDouble(p, "closing pressure tolerance", 9.80665, "Pa",
                    "the search stops when the closing pressure is bracketed this closely (9.80665 Pa = 0.1 cmH2O)",
                    io::Range::positive());
  return p;
}

std::shared_ptr<const model::AirwayOutput> buildAirway(const io::Deck &deck, const model::Scene &scene) {
  const ParameterList &a = deck.root().sublist("Airway");
  if (a.get<std::string>("face set").empty()) return nullptr;
  const auto &faces = faceSetAt(deck, scene.mesh, {"Airway", "face set"});
  require(deck, "wall file", "the wall's OBJ or STL file");
  require(deck, "start point", "the start of its centreline");
  require(deck, "end point", "the end of its centreline");
  if (vec3(a.get<Array<double>>("lateral axis")).isZero(0.0))
    throw io::DeckError(deck.where({"Airway", "lateral axis"}) + ": the axis is zero; the midsagittal plane needs a normal");
  auto out = std::make_shared<model::AirwayOutput>();
  out->contact = namedIndex(deck, "contact", scene.contacts, "contact", "Contact");
  out->pressureLoad = namedIndex(deck, "closing pressure load", scene.pressures, "follower pressure", "Loads");
  out->pressureTolerance = a.get<double>("closing pressure tolerance");
  airway::TriangleSet tongue = tongueTriangles(scene.mesh, faces, out->nodes);
  airway::CentrelineSettings centreline;
  centreline.midsagittalPoint = vec3(a.get<Array<double>>("midsagittal point"));
  centreline.lateralAxis = vec3(a.get<Array<double>>("lateral axis"));
  centreline.start = vec3(a.get<Array<double>>("start point"));
  centreline.end = vec3(a.get<Array<double>>("end point"));
  centreline.sections = a.get<int>("sections");
  try {
    airway::LumenSettings lumen{a.get<double>("closing area"), a.get<double>("contact gap"),
                                a.get<double>("closing width fraction")};
    if (a.get<double>("lateral half-width") > 0.0) lumen.lateralHalfWidth = a.get<double>("lateral half-width");
    out->lumen = std::make_shared<airway::AirwayLumen>(std::move(tongue), wallTriangles(deck), centreline, lumen);
  } catch (const std::invalid_argument &e) {
    throw io::DeckError(deck.where({"Airway"}) + ": " + e.what() +
                        " (check 'face set', 'wall file', 'midsagittal point', 'start point' and 'end point')");
  }
  return out;
}

}  // namespace glossa::input
