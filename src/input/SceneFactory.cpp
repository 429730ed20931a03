#include "input/SceneFactory.hpp"

#include "model/PointLocation.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>

#include "input/DeckPaths.hpp"
#include "input/DeckVector.hpp"
#include "io/deck/DeckError.hpp"
#include "io/deck/SpaceTimeExpression.hpp"
#include "io/deck/ParameterSpec.hpp"
#include "loads/BodyForce.hpp"
#include "mesh/BoxGenerator.hpp"
#include "mesh/CookMembraneGenerator.hpp"
#include "mesh/HexMesh.hpp"
#include "mesh/MeshRefinement.hpp"
#include "mesh/ReferenceCoordinates.hpp"
#include "mesh/QuarterCylinderGenerator.hpp"
#include "mesh/ThickCylinderGenerator.hpp"
#include "mesh/ThickSphereGenerator.hpp"
#include "input/TimeFunctionParameters.hpp"
#include "input/AirflowParameters.hpp"
#include "input/AirwayParameters.hpp"
#include "input/ContactParameters.hpp"
#include "input/DeckSets.hpp"
#include "input/MaterialFactory.hpp"
#include "input/MeshFileReading.hpp"
#include "input/SceneChecks.hpp"

namespace glossa::input {

// The scene is the model layer's; this layer only reads it from the deck.
using namespace glossa::model;

namespace {
using Teuchos::Array;
using Teuchos::ParameterList;

ParameterList meshParameters() {
  ParameterList p;
  io::declareString(p, "type", "box", "a built-in generator, or file (doc/meshes.md)",
                    {"box", "cook-membrane", "thick cylinder", "thick sphere", "quarter cylinder", "file"});
  io::declareString(p, "partitioner", "auto",
                    "how elements are shared out among MPI ranks: auto (Zoltan2 multijagged for a mesh file, "
                    "the built-in coordinate bisection for the generated meshes), or named",
                    {"auto", "coordinate bisection", "Zoltan2 multijagged", "Zoltan2 RCB"});
  ParameterList &file = p.sublist("File", false, "a mesh read from a file (type = file)");
  io::declareString(file, "path", "", "the mesh file, relative to the deck (ANSYS: the .node or the .elem)");
  io::declareString(file, "format", "auto", "by extension (.msh gmsh, .inp abaqus, .node/.elem ansys), or named",
                    {"auto", "gmsh", "abaqus", "ansys"});
  io::declareString(file, "moved nodes", "",
                    "a file of 'id x y z' lines [m] whose nodes replace those of the mesh file (its ids), before "
                    "the sets and the refinement: a mesh kept as published with some nodes moved, as the tongue's "
                    "interior nodes mended by inputs/tongue/mend_tongue.py; empty: none");
  io::declareInt(file, "refine", 0, "split every hexahedron into 8 this many times (sets carried over)",
                 io::Range::closed(0, 4));
  io::declareString(file, "ANSYS components", "", "ansys: APDL macro of element components (CreateMuscles.mac)");
  io::declareString(file, "ANSYS fibres", "",
                    "ansys: APDL macro of fibre polylines (Fibers.mac), muscles numbered as the components' "
                    "muscleName array; each muscle's polylines are available to 'direction field = polylines'");
  ParameterList externalPoints;
  ParameterList &point = externalPoints.sublist(io::kAnySublist);
  io::declareInt(point, "id", 0, "the node id the fibre macro uses for the point", io::Range::nonNegative());
  io::declareDoubleArray(point, "position", Array<double>(3, 0.0), "m", "where the point is", 3);
  file.set("ANSYS fibre anchors", externalPoints,
           "ansys: fibre vertices that are not mesh nodes (the tongue's styloid anchors 4037 and 4042), one "
           "sublist each");
  ParameterList nodeLists;
  ParameterList &list = nodeLists.sublist(io::kAnySublist);
  io::declareString(list, "file", "", "a list of node ids of the file (one per line): a node set of this name");
  file.set("Node lists", nodeLists, "ansys: node sets from lists of node ids, one sublist each");
  declareMeshCheckParameters(p);
  ParameterList &box = p.sublist("Box", false, "a structured box of hexahedra (type = box); face "
                                              "and node sets xmin, xmax, ymin, ymax, zmin, zmax");
  io::declareDoubleArray(box, "origin", Array<double>(3, 0.0), "m", "corner with the smallest coordinates", 3);
  io::declareDoubleArray(box, "lengths", Array<double>(3, 1e-3), "m", "edge lengths", 3, io::Range::positive());
  io::declareIntArray(box, "cells", Array<int>(3, 8), "elements along x, y, z", 3, io::Range::closed(1, 1000));
  ParameterList &cook = p.sublist("Cook membrane", false,
                                  "Cook's trapezoidal membrane (type = cook-membrane), corners "
                                  "(0,0), (48,44), (48,60), (0,44) mm, extruded in z; sets clamped, "
                                  "loaded, bottom, top, front, back; named point tip");
  io::declareInt(cook, "cells per side", 8, "elements along each in-plane direction", io::Range::closed(1, 1000));
  io::declareInt(cook, "cells through thickness", 1, "elements along z", io::Range::closed(1, 1000));
  io::declareDouble(cook, "thickness", 1.0, "mm", "extrusion depth", io::Range::positive());
  io::declareDouble(cook, "scale", 1e-3, "m/mm", "length unit of the corner coordinates", io::Range::positive());
  ParameterList &cylinder = p.sublist("Thick cylinder", false,
                                      "a quarter of a thick-walled cylinder (type = thick cylinder) about z, "
                                      "from +x to +y; sets inner, outer, y0, x0, zmin, zmax; named point inner");
  io::declareDouble(cylinder, "inner radius", 1e-3, "m", "", io::Range::positive());
  io::declareDouble(cylinder, "outer radius", 2e-3, "m", "", io::Range::positive());
  io::declareDouble(cylinder, "height", 0.25e-3, "m", "extent along z", io::Range::positive());
  io::declareIntArray(cylinder, "cells", Array<int>(std::vector<int>{8, 8, 1}), "radial, circumferential, axial", 3,
                      io::Range::closed(1, 1000));
  ParameterList &sphere = p.sublist("Thick sphere", false,
                                    "an octant (x, y, z >= 0) of a thick-walled spherical shell (type = thick "
                                    "sphere), three cubed-sphere patches of equal angles; sets inner, outer, "
                                    "x0, y0, z0; named points inner, outer on the x axis");
  io::declareDouble(sphere, "inner radius", 1e-3, "m", "", io::Range::positive());
  io::declareDouble(sphere, "outer radius", 2e-3, "m", "", io::Range::positive());
  io::declareInt(sphere, "radial cells", 4, "element layers through the wall", io::Range::closed(1, 1000));
  io::declareInt(sphere, "cells per patch side", 4, "elements along each edge of each of the three patches "
                 "(3 n^2 per layer)", io::Range::closed(1, 1000));
  ParameterList &quarter = p.sublist("Quarter cylinder", false,
                                     "a quarter of a solid cylinder on the plane y = 0 (type = quarter cylinder): "
                                     "axis through (0, R, 0) along z, x >= 0, y <= R, graded towards the lowest line "
                                     "x = y = 0 (Hertz contact, doc/contact.md); sets arc, top, x0, zmin, zmax; named "
                                     "points lowest, axis");
  io::declareDouble(quarter, "radius", 1e-2, "m", "the cylinder's radius R", io::Range::positive());
  io::declareDouble(quarter, "height", 1e-3, "m", "extent along z", io::Range::positive());
  io::declareIntArray(quarter, "cells", Array<int>(std::vector<int>{8, 8, 4, 12, 1}),
                      "along the arc: in the fine band (equal), from it to 45 degrees (growing), from 45 to 90 "
                      "degrees (equal); along each ray from the inner square to the arc (growing from the arc); "
                      "along z",
                      5, io::Range::closed(1, 1000));
  io::declareDouble(quarter, "fine band", 1e-3, "m",
                    "the band x in [0, this] of the arc meshed with equal cells, where contact is expected; "
                    "below R / sqrt 2", io::Range::positive());
  ParameterList &faces = p.sublist("Face sets", false,
                                   "derived face sets: the faces of an existing set (or of the whole "
                                   "boundary) whose centroid lies in a box and whose outward normal "
                                   "faces a direction");
  ParameterList &face = faces.sublist(io::kAnySublist);
  io::declareString(face, "from", "", "existing face set to select from; empty: every boundary face of the mesh");
  io::declareDoubleArray(face, "outward normal", Array<double>(3, 0.0), "",
                         "keep faces whose reference outward unit normal n has n . d >= 'minimum cosine', d "
                         "this direction normalised; zero: no condition on the normal", 3);
  io::declareDouble(face, "minimum cosine", 0.0, "", "the bound on n . d (cosine of the largest angle to d)",
                    io::Range::closed(-1, 1));
  io::declareDoubleArray(face, "box min", Array<double>(3, -1e300), "m", "lower corner of the selection box", 3);
  io::declareDoubleArray(face, "box max", Array<double>(3, 1e300), "m", "upper corner of the selection box", 3);
  ParameterList &elementSets = p.sublist("Element sets", false,
                                         "derived element sets: the elements of an existing set (or of the "
                                         "whole mesh) whose centroid lies in a box, e.g. the tissues of a "
                                         "generated mesh");
  ParameterList &elementSet = elementSets.sublist(io::kAnySublist);
  io::declareString(elementSet, "from", "", "existing element set to select from; empty: every element");
  io::declareDoubleArray(elementSet, "box min", Array<double>(3, -1e300), "m", "lower corner of the selection box", 3);
  io::declareDoubleArray(elementSet, "box max", Array<double>(3, 1e300), "m", "upper corner of the selection box", 3);
  io::declareString(p, "reference coordinates file", "",
                    "nodal coordinates that replace the mesh's as the reference (zero-strain) configuration, "
                    "e.g. written by glossa zero-strain: lines 'node x y z', node the 0-based index in this mesh, "
                    "relative to the deck; sets, named points and fibre directions stay those of the mesh as read "
                    "(doc/tongue.md, s8_1); a file for the mesh before 'refine' is carried to the refined "
                    "mesh (new nodes at the midpoints of its geometry); empty: the mesh as read");
  return p;
}

ParameterList dirichletParameters() {
  ParameterList p;
  io::declareString(p, "type", "fixed",
                    "fixed: the components are prescribed; elastic: a spring per node and component "
                    "pulls them towards the prescribed value (an elastic attachment, e.g. the hyoid)",
                    {"fixed", "elastic"});
  io::declareDouble(p, "stiffness", 0.0, "N/m",
                    "elastic: the support's total stiffness per component, shared equally among its nodes",
                    io::Range::nonNegative());
  io::declareString(p, "node set", "", "node set (or face set: its nodes) to constrain");
  io::declareString(p, "components", "x,y,z", "constrained components, comma separated",
                    {"x", "y", "z", "x,y", "x,z", "y,z", "x,y,z"});
  io::declareDoubleArray(p, "value", Array<double>(3, 0.0), "m",
                         "prescribed displacement (entries of free components ignored)", 3);
  for (const char *c : {"ux", "uy", "uz"})
    io::declareString(p, c, "",
                      std::string("the prescribed ") + c + " [m] of a constrained component as an expression of the "
                      "reference position X, Y, Z [m] and the time t [s], e.g. '1.2 * t * X' (+ - * / ^, sqrt, exp, "
                      "log, sin, cos, abs, a < b ? c : d); replaces value and time function for that component; "
                      "empty: value x time function");
  p.set("time function", timeFunctionParameters(), "scales the value in time");
  p.sublist("time function").set("type", std::string("constant"));
  return p;
}

ParameterList loadParameters() {
  ParameterList p;
  io::declareString(p, "type", "dead traction",
                    "dead traction: force per reference area, fixed direction; gravity: the weight "
                    "rho g of the material (density), by posture or direction; body force: rho a for "
                    "any acceleration a",
                    {"dead traction", "gravity", "body force", "follower pressure"});
  io::declareString(p, "face set", "", "dead traction, follower pressure: faces the load acts on");
  io::declareDouble(p, "pressure", 0.0, "Pa",
                    "follower pressure: p_max, sigma = -p I on the deformed faces (p > 0 compresses, p < 0 "
                    "is suction)");
  io::declareString(p, "profile", "uniform",
                    "follower pressure: uniform, or linear from 0 at 'P_A' to p_max at 'P_P' (paper §8.3)",
                    {"uniform", "linear"});
  io::declareDoubleArray(p, "P_A", Array<double>(3, 0.0), "m", "linear profile: where p = 0", 3);
  io::declareDoubleArray(p, "P_P", Array<double>(3, 0.0), "m", "linear profile: where p = p_max", 3);
  io::declareDoubleArray(p, "traction", Array<double>(3, 0.0), "Pa", "dead traction: traction vector at scale 1", 3);
  io::declareString(p, "posture", "upright",
                    "gravity: upright (along -y) or supine (along -x) in the body frame of doc/loads.md "
                    "(x anterior, y superior, z left), or custom ('direction')",
                    {"upright", "supine", "custom"});
  io::declareDouble(p, "g", 9.81, "m/s^2", "gravity: its magnitude", io::Range::nonNegative());
  io::declareDoubleArray(p, "direction", Array<double>(3, 0.0), "", "gravity, custom posture: direction of gravity", 3);
  io::declareDoubleArray(p, "acceleration", Array<double>(3, 0.0), "m/s^2", "body force: a at scale 1", 3);
  io::declareString(p, "element set", "", "gravity, body force: elements it acts on; empty: all");
  p.set("time function", timeFunctionParameters(), "scales the load in time");
  return p;
}

ParameterList namedPointParameters() {
  ParameterList p;
  io::declareDoubleArray(p, "position", Array<double>(3, 0.0), "m",
                         "reference position: at a mesh node (within 1e-6 of the smallest element edge) "
                         "the node's values; elsewhere inside the mesh a probe, its element's nodal values "
                         "interpolated by the trilinear shape functions (not a control point)", 3);
  return p;
}

// A path the deck gives, relative to the deck's own directory unless absolute.
// asRead, when given, receives the file's mesh before Mesh/File/refine (empty when not refined).
mesh::HexMesh buildMesh(const io::Deck &deck, std::vector<std::string> &notes, mesh::HexMesh *asRead = nullptr) {
  const ParameterList &p = deck.root().sublist("Mesh");
  mesh::HexMesh m;
  try {
    if (p.get<std::string>("type") == "box") {
      const auto &b = p.sublist("Box");
      const auto &c = b.get<Array<int>>("cells");
      m = mesh::generateBox(vec3(b.get<Array<double>>("origin")), vec3(b.get<Array<double>>("lengths")),
                            {c[0], c[1], c[2]});
    } else if (p.get<std::string>("type") == "file") {
      const auto &f = p.sublist("File");
      m = readFileMesh(deck, notes);
      if (f.get<int>("refine") > 0) {
        if (asRead) *asRead = m;
        m = mesh::refineUniformly(m, f.get<int>("refine"));
      }
    } else if (p.get<std::string>("type") == "thick cylinder") {
      const auto &c = p.sublist("Thick cylinder");
      const auto &n = c.get<Array<int>>("cells");
      m = mesh::generateThickCylinder(c.get<double>("inner radius"), c.get<double>("outer radius"),
                                      c.get<double>("height"), {n[0], n[1], n[2]});
    } else if (p.get<std::string>("type") == "quarter cylinder") {
      const auto &c = p.sublist("Quarter cylinder");
      const auto &n = c.get<Array<int>>("cells");
      m = mesh::generateQuarterCylinder(c.get<double>("radius"), c.get<double>("height"),
                                        {n[0], n[1], n[2], n[3], n[4]}, c.get<double>("fine band"));
    } else if (p.get<std::string>("type") == "thick sphere") {
      const auto &c = p.sublist("Thick sphere");
      m = mesh::generateThickSphere(c.get<double>("inner radius"), c.get<double>("outer radius"),
                                    c.get<int>("radial cells"), c.get<int>("cells per patch side"));
    } else {
      const auto &c = p.sublist("Cook membrane");
      m = mesh::generateCookMembrane(c.get<int>("cells per side"), c.get<int>("cells through thickness"),
                                     c.get<double>("thickness"), c.get<double>("scale"));
    }
  } catch (const std::invalid_argument &e) {
    throw io::DeckError(deck.where({"Mesh"}) + ": " + e.what());
  }
  const ParameterList &faces = p.sublist("Face sets");
  for (auto it = faces.begin(); it != faces.end(); ++it) {
    const std::string &name = faces.name(it);
    const ParameterList &f = faces.sublist(name);
    const std::string from = f.get<std::string>("from");
    if (!from.empty() && !m.faceSets.count(from))
      throw io::DeckError(deck.where({"Mesh", "Face sets", name, "from"}) + ": no face set '" + from + "'");
    auto selected = mesh::facesInBox(m, from.empty() ? mesh::boundaryFaces(m) : m.faceSets.at(from),
                                     vec3(f.get<Array<double>>("box min")), vec3(f.get<Array<double>>("box max")));
    const Eigen::Vector3d facing = vec3(f.get<Array<double>>("outward normal"));
    if (facing.norm() > 0.0) selected = mesh::facesFacing(m, selected, facing, f.get<double>("minimum cosine"));
    if (selected.empty())
      throw io::DeckError(deck.where({"Mesh", "Face sets", name}) + ": the box and normal select no face of " +
                          (from.empty() ? std::string("the boundary") : "'" + from + "'"));
    m.faceSets[name] = std::move(selected);
  }
  const ParameterList &elementSets = p.sublist("Element sets");
  for (auto it = elementSets.begin(); it != elementSets.end(); ++it) {
    const std::string &name = elementSets.name(it);
    const ParameterList &set = elementSets.sublist(name);
    const std::string from = set.get<std::string>("from");
    if (!from.empty() && !m.elementSets.count(from))
      throw io::DeckError(deck.where({"Mesh", "Element sets", name, "from"}) + ": no element set '" + from + "'");
    const Eigen::Vector3d lo = vec3(set.get<Array<double>>("box min")), hi = vec3(set.get<Array<double>>("box max"));
    std::vector<mesh::ElementId> selected;
    auto consider = [&](mesh::ElementId e) {
      const Eigen::Vector3d c = m.elementCoordinates(e).colwise().mean().transpose();
      if ((c.array() >= lo.array()).all() && (c.array() <= hi.array()).all()) selected.push_back(e);
    };
    if (from.empty())
      for (std::size_t e = 0; e < m.numElements(); ++e) consider(static_cast<mesh::ElementId>(e));
    else
      for (const auto e : m.elementSets.at(from)) consider(e);
    if (selected.empty())
      throw io::DeckError(deck.where({"Mesh", "Element sets", name}) + ": the box selects no element of " +
                          (from.empty() ? std::string("the mesh") : "'" + from + "'"));
    m.elementSets[name] = std::move(selected);
  }
  return m;
}

// Mesh/reference coordinates file (§8.1): the zero-strain configuration replaces the node
// positions after everything that selects by geometry (face sets by box and normal, named points,
// fibre directions from the polylines) has been done on the mesh as read: those are labels of the
// imaged anatomy (model::useReferenceNodes). A file for the mesh as read (`asRead`, non-empty when
// Mesh/File/refine > 0) is carried to the refinement: its new nodes at the midpoints of the
// zero-strain geometry's edges, faces and cells, so one zero-strain configuration serves the coarse,
// medium and fine tongues (on a refined mesh it is then the coarse one's, not its own: doc/tongue.md).
void replaceReferenceCoordinates(const io::Deck &deck, Scene &scene, const mesh::HexMesh &asRead) {
  const std::string file = deck.root().sublist("Mesh").get<std::string>("reference coordinates file");
  if (file.empty()) return;
  const std::filesystem::path q = relativeToDeck(deck, file);
  try {
    const bool refined = asRead.numNodes() > 0 && asRead.numNodes() != scene.mesh.numNodes();
    if (refined && mesh::countReferenceCoordinates(q.string()) == asRead.numNodes()) {
      const int levels = deck.root().sublist("Mesh").sublist("File").get<int>("refine");
      useReferenceNodes(scene, mesh::refinedPositions(
                                   asRead, mesh::readReferenceCoordinates(q.string(), asRead.numNodes()), levels));
    } else {
      useReferenceNodes(scene, mesh::readReferenceCoordinates(q.string(), scene.mesh.numNodes()));
    }
  } catch (const std::runtime_error &e) {
    std::string also;
    if (asRead.numNodes() > 0 && asRead.numNodes() != scene.mesh.numNodes())
      also = " (or " + std::to_string(asRead.numNodes()) + ", the mesh's before Mesh/File/refine)";
    throw io::DeckError(deck.where({"Mesh", "reference coordinates file"}) + ": " + e.what() + also);
  }
}

std::string knownSets(const mesh::HexMesh &m) {
  std::string s;
  for (const auto &[name, nodes] : m.nodeSets) s += (s.empty() ? "" : ", ") + name;
  for (const auto &[name, faces] : m.faceSets)
    if (!m.nodeSets.count(name)) s += (s.empty() ? "" : ", ") + name;
  return s;
}
} // namespace

void declareSceneParameters(ParameterList &schema) {
  schema.set("Mesh", meshParameters(), "the mesh and its sets");
  schema.set("Material", materialParameters(), "the material of every element");
  ParameterList bcs;
  bcs.set(io::kAnySublist, dirichletParameters(), "one condition: fixed (Dirichlet) or elastic");
  schema.set("Boundary conditions", bcs, "prescribed displacements and elastic supports, one sublist each");
  ParameterList loads;
  loads.set(io::kAnySublist, loadParameters(), "one load");
  schema.set("Loads", loads, "surface loads, one sublist each");
  ParameterList contacts;
  contacts.set(io::kAnySublist, contactParameters(),
               "one face set against one rigid obstacle, another face set or itself");
  schema.set("Contact", contacts, "contact with rigid obstacles, one sublist each (doc/contact.md)");
  schema.set("Airway", airwayParameters(), "the airway's lumen between the tongue and a rigid wall (doc/airway.md)");
  schema.set("Airflow", airflowParameters(),
             "the 1D airflow through the airway's lumen, its pressure on the airway faces (doc/airflow.md)");
  ParameterList points;
  points.set(io::kAnySublist, namedPointParameters(), "one named point");
  schema.set("Named points", points,
             "points whose displacement goes to traces.csv and summary.json (a generator's own "
             "named points, e.g. 'tip', are traced too)");
}

namespace {
// Boundary conditions: each a node set's fixed components, their values or expressions, and
// an elastic support's stiffness.
std::vector<DirichletCondition> buildBoundaryConditions(const io::Deck &deck, const mesh::HexMesh &m, double endTime) {
  std::vector<DirichletCondition> conditions;
  const ParameterList &bcs = deck.root().sublist("Boundary conditions");
  for (auto it = bcs.begin(); it != bcs.end(); ++it) {
    const std::string &name = bcs.name(it);
    const ParameterList &b = bcs.sublist(name);
    DirichletCondition bc;
    bc.name = name;
    const std::string set = b.get<std::string>("node set");
    if (m.nodeSets.count(set)) bc.nodes = m.nodeSets.at(set);
    else if (m.faceSets.count(set)) bc.nodes = m.nodesOfFaceSet(set);
    else
      throw io::DeckError(deck.where({"Boundary conditions", name, "node set"}) + ": no node or face set '" +
                          set + "'; the mesh has: " + knownSets(m));
    const std::string comps = b.get<std::string>("components");
    for (int i = 0; i < 3; ++i) bc.fixed[i] = comps.find("xyz"[i]) != std::string::npos;
    bc.value = vec3(b.get<Array<double>>("value"));
    bc.scale = timeFunctionAt(deck, {"Boundary conditions", name, "time function"}, endTime);
    for (int c = 0; c < 3; ++c) {
      const char *key = c == 0 ? "ux" : c == 1 ? "uy" : "uz";
      const std::string text = b.get<std::string>(key);
      if (text.find_first_not_of(" \t") == std::string::npos) continue;
      if (!bc.fixed[c])
        throw io::DeckError(deck.where({"Boundary conditions", name, key}) + ": component " + std::string(1, "xyz"[c]) +
                            " is not among the condition's components '" + comps + "'");
      std::shared_ptr<const io::SpaceTimeExpression> expression;
      try {
        expression = std::make_shared<const io::SpaceTimeExpression>(text);
      } catch (const std::invalid_argument &e) {
        throw io::DeckError(deck.where({"Boundary conditions", name, key}) + ": " + e.what());
      }
      bc.expression[c] = [expression](const Eigen::Vector3d &X, double t) { return (*expression)(X.x(), X.y(), X.z(), t); };
    }
    if (b.get<std::string>("type") == "elastic") {
      const double k = b.get<double>("stiffness");
      if (!(k > 0.0))
        throw io::DeckError(deck.where({"Boundary conditions", name, "stiffness"}) +
                            ": an elastic support needs a stiffness > 0 [N/m] (its total, shared by its " +
                            std::to_string(bc.nodes.size()) + " nodes)");
      if (bc.nodes.empty())
        throw io::DeckError(deck.where({"Boundary conditions", name, "node set"}) + ": the set '" + set + "' is empty");
      bc.nodeStiffness = k / static_cast<double>(bc.nodes.size());
    }
    conditions.push_back(std::move(bc));
  }
  return conditions;
}

// Loads: follower pressures, gravity and body forces, dead tractions (a follower load makes the
// tangent unsymmetric).
void buildLoads(const io::Deck &deck, const mesh::HexMesh &m, double endTime, Scene &scene) {
  const ParameterList &loads = deck.root().sublist("Loads");
  for (auto it = loads.begin(); it != loads.end(); ++it) {
    const std::string &name = loads.name(it);
    const ParameterList &l = loads.sublist(name);
    const auto type = l.get<std::string>("type");
    if (type == "follower pressure") {
      FollowerPressureLoad load;
      load.name = name;
      load.faces = faceSetAt(deck, m, {"Loads", name, "face set"});
      const TimeFunction b = timeFunctionAt(deck, {"Loads", name, "time function"}, endTime);
      const double pMax = l.get<double>("pressure");
      if (l.get<std::string>("profile") == "uniform") {
        load.pressure = loads::PressureField::uniform(pMax, b);
      } else {
        try {
          load.pressure = loads::PressureField::linear(pMax, vec3(l.get<Array<double>>("P_A")),
                                                       vec3(l.get<Array<double>>("P_P")), b);
        } catch (const std::invalid_argument &e) {
          throw io::DeckError(deck.where({"Loads", name, "P_P"}) + ": " + e.what());
        }
      }
      scene.pressures.push_back(std::move(load));
      scene.symmetricTangent = false; // a follower load's tangent is not symmetric: GMRES
      continue;
    }
    if (type != "dead traction") {
      BodyForceLoad body;
      body.name = name;
      body.elements = elementSetOrAll(deck, m, {"Loads", name, "element set"});
      const double g = l.get<double>("g");
      const auto posture = l.get<std::string>("posture");
      if (type == "body force") {
        body.acceleration = vec3(l.get<Array<double>>("acceleration"));
      } else if (posture == "custom") {
        const Eigen::Vector3d d = vec3(l.get<Array<double>>("direction"));
        if (!(d.norm() > 0.0))
          throw io::DeckError(deck.where({"Loads", name, "direction"}) + " is zero; a custom posture needs the "
                              "direction of gravity");
        body.acceleration = g * d.normalized();
      } else {
        body.acceleration = loads::postureGravity(posture, g);
      }
      body.gravity = type == "gravity";
      body.scale = timeFunctionAt(deck, {"Loads", name, "time function"}, endTime);
      scene.bodyForces.push_back(std::move(body));
      continue;
    }
    DeadTractionLoad load;
    load.name = name;
    load.faces = faceSetAt(deck, m, {"Loads", name, "face set"});
    load.traction = vec3(l.get<Array<double>>("traction"));
    load.scale = timeFunctionAt(deck, {"Loads", name, "time function"}, endTime);
    scene.tractions.push_back(std::move(load));
  }
}

// The airflow's pressure on the Airway section's face set: a follower pressure whose Gauss-point
// values the run sets from the flow at every coupling iteration (doc/airflow.md).
void addAirflowLoad(const io::Deck &deck, const mesh::HexMesh &m, double endTime, Scene &scene) {
  if (parseAirflowParameters(deck, endTime).drive == AirflowDrive::off) return;
  if (deck.root().sublist("Airway").get<std::string>("face set").empty())
    throw io::DeckError(deck.where({"Airflow", "driven by"}) +
                        ": the airflow runs through the airway's lumen, which the Airway section defines: give "
                        "Airway/face set, wall file, start point and end point (doc/airway.md)");
  FollowerPressureLoad load;
  load.name = "Airflow";
  load.faces = faceSetAt(deck, m, {"Airway", "face set"});
  load.given = std::make_shared<std::vector<std::array<double, 4>>>(load.faces.size(), std::array<double, 4>{});
  scene.airflowLoad = static_cast<int>(scene.pressures.size());
  scene.pressures.push_back(std::move(load));
  scene.symmetricTangent = false; // a follower load's tangent is not symmetric: GMRES
}

// The traced points: the generator's named points and the deck's, each at a node or interpolated
// in the element that holds it.
void traceNamedPoints(const io::Deck &deck, Scene &scene) {
  mesh::HexMesh &m = scene.mesh;
  for (const auto &[name, point] : m.namedPoints) scene.tracedPoints.push_back(name);
  const ParameterList &points = deck.root().sublist("Named points");
  for (auto it = points.begin(); it != points.end(); ++it) {
    const std::string &name = points.name(it);
    const Eigen::Vector3d x = vec3(points.sublist(name).get<Array<double>>("position"));
    const mesh::NodeId node = m.nearestNode(x);
    double hMin = std::numeric_limits<double>::infinity();
    for (const auto &e : m.elements) hMin = std::min(hMin, (m.nodes[e[1]] - m.nodes[e[0]]).norm());
    if ((m.nodes[node] - x).norm() <= 1e-6 * hMin) {
      m.namedPoints[name] = {x, node, {}};
    } else if (auto probe = probeAt(m, x)) {
      m.namedPoints[name] = std::move(*probe); // interpolated in its element
    } else {
      std::ostringstream s;
      s << deck.where({"Named points", name, "position"}) << ": outside the mesh (nearest node " << node << " at "
        << m.nodes[node].transpose() << ")";
      throw io::DeckError(s.str());
    }
    if (std::find(scene.tracedPoints.begin(), scene.tracedPoints.end(), name) == scene.tracedPoints.end())
      scene.tracedPoints.push_back(name);
  }
}

} // namespace

Scene buildScene(const io::Deck &deck, double endTime) {
  Scene scene;
  mesh::HexMesh asRead;
  scene.mesh = buildMesh(deck, scene.meshNotes, &asRead);
  mesh::HexMesh &m = scene.mesh;

  BuiltMaterial material = buildMaterial(deck, m, endTime);
  scene.tissues = std::move(material.tissues);
  scene.elementTissue = std::move(material.elementTissue);
  scene.muscles = std::move(material.muscles);
  scene.formulation = material.plainQ1 ? ElementFormulation::PlainQ1 : ElementFormulation::Q1P0;
  {
    const ParameterList &m = deck.root().sublist("Mesh");
    const std::string partitioner = m.get<std::string>("partitioner");
    scene.partitioner = partitioner == "coordinate bisection" ? Partitioner::coordinateBisection
                        : partitioner == "Zoltan2 RCB"        ? Partitioner::zoltan2Rcb
                        : partitioner == "Zoltan2 multijagged" || m.get<std::string>("type") == "file"
                            ? Partitioner::zoltan2MultiJagged
                            : Partitioner::coordinateBisection;
  }
  scene.symmetricTangent = material.symmetricTangent;

  scene.dirichlet = buildBoundaryConditions(deck, m, endTime);
  buildLoads(deck, m, endTime, scene);
  addAirflowLoad(deck, m, endTime, scene);
  buildContacts(deck, m, endTime, scene);
  traceNamedPoints(deck, scene);
  if (scene.tracedPoints.empty())
    scene.meshNotes.push_back("no named points: traces.csv and final_displacement will be empty; name points "
                              "in the deck's 'Named points' (any position inside the mesh) to trace them");
  replaceReferenceCoordinates(deck, scene, asRead);
  checkScene(deck, scene);
  return scene;
}

} // namespace glossa::input
