#include "mesh/GmshAssembly.hpp"

#include <algorithm>
#include <sstream>

#include "mesh/ImportSupport.hpp"
#include "mesh/MeshError.hpp"

namespace glossa::mesh::gmsh {

void fail(const std::string &file, Place place, const std::string &reason) {
  if (place.binary) throw MeshError(file + ": byte " + std::to_string(place.byte) + ": " + reason);
  importing::fail(file, place.line, reason);
}

namespace {

// The Gmsh element types (numbers of the MSH format) a hexahedral mesh may meet, up to third
// order: enough to name what is refused and, in binary files, to step over what is skipped.
const std::map<std::int64_t, ElementType> kTypes = {
    {1, {1, 2, 2, "2-node line"}},           {2, {2, 3, 3, "3-node triangle"}},
    {3, {2, 4, 4, "4-node quadrangle"}},     {4, {3, 4, 4, "4-node tetrahedron"}},
    {5, {3, 8, 8, "8-node hexahedron"}},     {6, {3, 6, 6, "6-node prism"}},
    {7, {3, 5, 5, "5-node pyramid"}},        {8, {1, 3, 2, "3-node line"}},
    {9, {2, 6, 3, "6-node triangle"}},       {10, {2, 9, 4, "9-node quadrangle"}},
    {11, {3, 10, 4, "10-node tetrahedron"}}, {12, {3, 27, 8, "27-node hexahedron"}},
    {13, {3, 18, 6, "18-node prism"}},       {14, {3, 14, 5, "14-node pyramid"}},
    {15, {0, 1, 1, "1-node point"}},         {16, {2, 8, 4, "8-node quadrangle"}},
    {17, {3, 20, 8, "20-node hexahedron"}},  {18, {3, 15, 6, "15-node prism"}},
    {19, {3, 13, 5, "13-node pyramid"}},     {20, {2, 9, 3, "9-node triangle"}},
    {21, {2, 10, 3, "10-node triangle"}},    {26, {1, 4, 2, "4-node line"}},
    {29, {3, 20, 4, "20-node tetrahedron"}}, {36, {2, 16, 4, "16-node quadrangle"}},
    {92, {3, 64, 8, "64-node hexahedron"}}};

// What each entity dimension is read as. Hexahedra of second order are read by their corners;
// a face set's quadrangles and a node set's lines likewise (their other nodes are not corners of
// the trilinear mesh).
bool isRead(int dim, std::int64_t type) {
  switch (dim) {
    case 3:
      return type == 5 || type == 12 || type == 17;
    case 2:
      return type == 3 || type == 10 || type == 16;
    case 1:
      return type == 1 || type == 8;
    default:
      return type == 15;
  }
}

bool oneOf(std::int64_t type, std::initializer_list<std::int64_t> types) {
  return std::find(types.begin(), types.end(), type) != types.end();
}

const char *kSubdivide = "'Mesh.SubdivisionAlgorithm = 2;' (every element split into hexahedra)";

}  // namespace

const ElementType *elementType(std::int64_t type) {
  const auto it = kTypes.find(type);
  return it == kTypes.end() ? nullptr : &it->second;
}

std::string typeName(std::int64_t type) {
  const ElementType *t = elementType(type);
  return "type " + std::to_string(type) + (t ? std::string(" (") + t->name + ")" : "");
}

Assembly::Assembly(std::string file) : file_(std::move(file)) { result_.source = file_; }

void Assembly::physicalName(int dim, std::int64_t tag, std::string name) {
  physicalNames_[{dim, tag}] = std::move(name);
}

void Assembly::node(std::int64_t tag, const Eigen::Vector3d &x, Place place) {
  const NodeId index = static_cast<NodeId>(result_.mesh.nodes.size());
  if (!nodeIndex_.emplace(tag, index).second) fail(place, "duplicate node tag " + std::to_string(tag));
  result_.mesh.nodes.push_back(x);
  result_.nodeFileIds.push_back(tag);
  cornerNode_.push_back(false);
  midsideNode_.push_back(false);
}

void Assembly::elementTag(std::int64_t tag, Place place) {
  if (!elementTags_.insert(tag).second) fail(place, "duplicate element tag " + std::to_string(tag));
}

bool Assembly::accepts(int dim, std::int64_t type, bool grouped, const std::function<std::string()> &entity,
                       Place place) {
  if (isRead(dim, type)) return dim == 3 || grouped;
  if (dim != 3 && !grouped) return false;  // an unused element of an ungrouped entity
  const std::string where = entity();
  const ElementType *known = elementType(type);
  const std::string gmshType =
      "Gmsh type " + std::to_string(type) + (known ? std::string(", ") + known->name : "");
  if (dim == 3 && oneOf(type, {4, 11, 29})) {
    fail(place, where + " contains tetrahedra (" + gmshType +
                    "): Glossa needs hexahedra; mesh with Recombine/Transfinite (a transfinite volume, or an "
                    "extrusion of recombined surfaces with Layers and Recombine) or " +
                    kSubdivide);
  }
  if (dim == 3 && oneOf(type, {6, 13, 18})) {
    fail(place, where + " contains prisms (" + gmshType +
                    "): Glossa needs hexahedra; prisms come from extruding triangles: 'Recombine Surface' "
                    "before extruding, or " +
                    kSubdivide);
  }
  if (dim == 3 && oneOf(type, {7, 14, 19})) {
    fail(place, where + " contains pyramids (" + gmshType +
                    "): Glossa needs hexahedra; pyramids join hexahedra to tetrahedra: make the whole "
                    "volume transfinite and recombined, or " +
                    kSubdivide);
  }
  if (dim == 2 && oneOf(type, {2, 9, 20, 21})) {
    // Refused at the end: Gmsh writes surfaces before volumes, and when the volume holds
    // tetrahedra, saying so is the more useful message.
    if (!pendingRefusal_) {
      pendingRefusal_ = std::make_pair(place, where + " contains triangles (" + gmshType +
                                                  "): a face set is made of hexahedron faces, quadrangles; "
                                                  "'Recombine Surface' or " +
                                                  kSubdivide);
    }
    return false;
  }
  fail(place, "element " + typeName(type) + " in " + where +
                  ": Glossa reads hexahedra (Gmsh types 5, 17, 12) in volumes and quadrangles (3, 16, 10), "
                  "lines (1, 8) and points (15) in physical groups");
}

NodeId Assembly::nodeOf(std::int64_t tag, std::int64_t element, Place place) const {
  const auto it = nodeIndex_.find(tag);
  if (it == nodeIndex_.end()) {
    fail(place, "element " + std::to_string(element) + " refers to node " + std::to_string(tag) +
                    ", which $Nodes does not define");
  }
  return it->second;
}

void Assembly::element(int dim, std::int64_t type, std::int64_t tag, std::int64_t entity,
                       const std::vector<std::int64_t> &nodeTags, const std::vector<std::int64_t> &physicals,
                       Place place) {
  const ElementType &t = *elementType(type);
  if (static_cast<int>(nodeTags.size()) != t.nodes) {
    fail(place, "element " + std::to_string(tag) + " of " + typeName(type) + " needs " +
                    std::to_string(t.nodes) + " nodes, found " + std::to_string(nodeTags.size()));
  }
  std::vector<NodeId> nodes;
  for (int a = 0; a < t.nodes; ++a) {
    const NodeId n = nodeOf(nodeTags[static_cast<std::size_t>(a)], tag, place);
    (a < t.corners ? cornerNode_ : midsideNode_)[static_cast<std::size_t>(n)] = true;
    nodes.push_back(n);
  }
  if (t.corners < t.nodes) ++secondOrderCount_[type];
  if (dim == 3) {
    Hex hex;
    std::copy(nodes.begin(), nodes.begin() + 8, hex.begin());  // Gmsh order = VTK order
    // MSH 2 has one physical tag per element line and writes an element of an entity in k
    // groups as k elements with new tags: the same element, so its copies only add groups. A
    // true duplicate (same groups) is kept and refused by the mesh checks.
    auto [it, added] = hexByEntityAndNodes_.emplace(std::make_pair(entity, hex), result_.mesh.numElements());
    if (!added && !physicals.empty()) {
      std::vector<std::int64_t> &groups = elementPhysicals_[static_cast<std::size_t>(it->second)];
      const bool copy = std::none_of(physicals.begin(), physicals.end(), [&](std::int64_t p) {
        return std::find(groups.begin(), groups.end(), p) != groups.end();
      });
      if (copy) {
        for (std::int64_t p : physicals) volumeMembers_[p].push_back(it->second);
        groups.insert(groups.end(), physicals.begin(), physicals.end());
        return;
      }
    }
    const ElementId e = static_cast<ElementId>(result_.mesh.numElements());
    result_.mesh.elements.push_back(hex);
    result_.elementFileIds.push_back(tag);
    elementPlaces_.push_back(place);
    elementPhysicals_.push_back(physicals);
    for (std::int64_t p : physicals) volumeMembers_[p].push_back(e);
  } else if (dim == 2) {
    for (std::int64_t p : physicals)
      surfaceMembers_[p].push_back({{nodes[0], nodes[1], nodes[2], nodes[3]}, place, tag});
  } else {
    for (std::int64_t p : physicals) {
      auto &members = lowerMembers_[{dim, p}];
      members.insert(members.end(), nodes.begin(), nodes.begin() + t.corners);
    }
  }
}

std::string Assembly::entityName(int dim, std::int64_t tag,
                                 const std::vector<std::int64_t> &physicals) const {
  static const char *kinds[4] = {"point", "curve", "surface", "volume"};
  std::string s = std::string(kinds[dim]) + " entity " + std::to_string(tag);
  for (std::size_t i = 0; i < physicals.size(); ++i) {
    s += (i == 0 ? " (physical '" : ", '") + groupName(dim, physicals[i]) + "'";
  }
  return s + (physicals.empty() ? "" : ")");
}

std::string Assembly::groupName(std::int64_t dim, std::int64_t tag) const {
  const auto it = physicalNames_.find({dim, tag});
  if (it != physicalNames_.end()) return it->second;
  return "physical" + std::to_string(dim) + "d_" + std::to_string(tag);
}

// A second-order element is read by its corners, so the nodes only such elements used (edge,
// face and centre nodes) would be nodes of no element, which the mesh checks before a run
// refuse. They are dropped here and the others renumbered in file order. Nodes that no element
// uses at all are kept: they are the file's, and the checks report them.
void Assembly::dropMidsideNodes() {
  if (secondOrderCount_.empty()) return;
  const std::size_t n = result_.mesh.nodes.size();
  std::vector<NodeId> newIndex(n, -1);
  std::vector<Eigen::Vector3d> nodes;
  std::vector<std::int64_t> fileIds;
  for (std::size_t i = 0; i < n; ++i) {
    if (midsideNode_[i] && !cornerNode_[i]) continue;
    newIndex[i] = static_cast<NodeId>(nodes.size());
    nodes.push_back(result_.mesh.nodes[i]);
    fileIds.push_back(result_.nodeFileIds[i]);
  }
  const std::size_t dropped = n - nodes.size();
  result_.mesh.nodes = std::move(nodes);
  result_.nodeFileIds = std::move(fileIds);
  // Every element, quadrangle and set member below is a corner, hence kept.
  for (Hex &hex : result_.mesh.elements) {
    for (NodeId &a : hex) a = newIndex[static_cast<std::size_t>(a)];
  }
  for (auto &[tag, quads] : surfaceMembers_) {
    for (Quad &q : quads) {
      for (NodeId &a : q.nodes) a = newIndex[static_cast<std::size_t>(a)];
    }
  }
  for (auto &[key, members] : lowerMembers_) {
    for (NodeId &a : members) a = newIndex[static_cast<std::size_t>(a)];
  }
  std::ostringstream note;
  note << file_ << ": second-order elements read by their corner nodes (";
  bool first = true;
  for (const auto &[type, count] : secondOrderCount_) {
    note << (first ? "" : ", ") << count << " of Gmsh " << typeName(type);
    first = false;
  }
  note << "): the geometry is made trilinear (curved edges become straight), and the " << dropped
       << " nodes only they used (edge, face and centre nodes) are dropped, the others renumbered in file "
          "order";
  result_.notes.push_back(note.str());
}

ImportedMesh Assembly::finish(Place end) {
  HexMesh &mesh = result_.mesh;
  if (pendingRefusal_) fail(pendingRefusal_->first, pendingRefusal_->second);
  if (mesh.elements.empty()) {
    fail(end,
         "no hexahedra (Gmsh types 5, 17, 12) in the file: mesh the volume (gmsh -3) and give it a "
         "physical group (Gmsh saves only the elements of physical groups)");
  }
  dropMidsideNodes();
  result_.indexFileIds();
  importing::checkElements(mesh, result_.elementFileIds, [&](std::size_t e, const std::string &reason) {
    fail(elementPlaces_[e], reason);
  });
  if (!physicalNames_.empty() && volumeMembers_.empty() && surfaceMembers_.empty() && lowerMembers_.empty()) {
    // Gmsh's MSH 2 writer with Mesh.SaveAll = 1 (-save_all) writes physical tag 0 everywhere.
    result_.notes.push_back(file_ +
                            ": $PhysicalNames names groups but no element carries a physical tag, so "
                            "the mesh has no sets (Gmsh's MSH 2 writer does this with -save_all; save as "
                            "MSH 4.1 or without it)");
  }
  for (auto &[tag, members] : volumeMembers_) {
    importing::sortUnique(members);
    mesh.elementSets[groupName(3, tag)] = members;
  }
  const importing::FaceLocator locator(mesh);
  for (const auto &[tag, quads] : surfaceMembers_) {
    const std::string name = groupName(2, tag);
    std::vector<ElementFace> faces;
    std::vector<NodeId> nodes;
    for (const Quad &q : quads) {
      ElementFace face;
      if (!locator.find(q.nodes, face)) {
        fail(q.place, "quadrangle " + std::to_string(q.tag) + " of physical surface '" + name +
                          "' is not a face of any hexahedron");
      }
      faces.push_back(face);
      nodes.insert(nodes.end(), q.nodes.begin(), q.nodes.end());
    }
    importing::sortUnique(faces);
    mesh.faceSets[name] = faces;
    auto &set = mesh.nodeSets[name];
    set.insert(set.end(), nodes.begin(), nodes.end());
    importing::sortUnique(set);
  }
  for (auto &[key, nodes] : lowerMembers_) {
    auto &set = mesh.nodeSets[groupName(key.first, key.second)];
    set.insert(set.end(), nodes.begin(), nodes.end());
    importing::sortUnique(set);
  }
  return std::move(result_);
}

}  // namespace glossa::mesh::gmsh
