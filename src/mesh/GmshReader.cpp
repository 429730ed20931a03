#include "mesh/GmshReader.hpp"

#include <map>
#include <set>
#include <stdexcept>

#include "mesh/ImportSupport.hpp"

namespace glossa::mesh {

using importing::LineReader;
using importing::parseDouble;
using importing::parseInt;
using importing::splitWhitespace;
using importing::trim;

namespace {

// Gmsh element types (the numbers of the MSH format) that a hexahedral mesh may meet: their
// node counts for parsing and their names for messages.
struct GmshType {
  int nodes;
  const char *name;
};
const std::map<std::int64_t, GmshType> kTypes = {
    {1, {2, "2-node line"}},        {2, {3, "3-node triangle"}},       {3, {4, "4-node quadrangle"}},
    {4, {4, "4-node tetrahedron"}}, {5, {8, "8-node hexahedron"}},     {6, {6, "6-node prism"}},
    {7, {5, "5-node pyramid"}},     {8, {3, "3-node line"}},           {9, {6, "6-node triangle"}},
    {10, {9, "9-node quadrangle"}}, {11, {10, "10-node tetrahedron"}}, {12, {27, "27-node hexahedron"}},
    {13, {18, "18-node prism"}},    {14, {14, "14-node pyramid"}},     {15, {1, "1-node point"}},
    {16, {8, "8-node quadrangle"}}, {17, {20, "20-node hexahedron"}},  {18, {15, "15-node prism"}},
    {19, {13, "13-node pyramid"}}};

std::string typeName(std::int64_t type) {
  const auto it = kTypes.find(type);
  return "type " + std::to_string(type) +
         (it == kTypes.end() ? "" : std::string(" (") + it->second.name + ")");
}

// The element type each entity dimension must hold to be mapped onto the hexahedral mesh.
constexpr std::int64_t kMappedType[4] = {15, 1, 3, 5};

class GmshParser {
 public:
  explicit GmshParser(const std::string &file) : in_(file) { result_.source = file; }

  ImportedMesh parse() {
    std::string line;
    bool haveFormat = false, haveNodes = false, haveElements = false;
    while (in_.next(line)) {
      const std::string name = trim(line);
      if (name.empty()) continue;
      if (name[0] != '$') in_.fail("expected a section header ($Name), found '" + name + "'");
      const std::string section = name.substr(1);
      if (section == "MeshFormat") {
        readFormat();
        haveFormat = true;
        continue;
      }
      if (!haveFormat) in_.fail("the file must start with $MeshFormat");
      if (section == "PhysicalNames") {
        readPhysicalNames();
      } else if (section == "Entities") {
        readEntities();
      } else if (section == "PartitionedEntities") {
        in_.fail("partitioned MSH files are not supported; save the mesh unpartitioned");
      } else if (section == "Nodes") {
        readNodes();
        haveNodes = true;
      } else if (section == "Elements") {
        if (!haveNodes) in_.fail("$Elements before $Nodes");
        readElements();
        haveElements = true;
      } else {
        skipSection(section);
      }
    }
    if (!haveFormat) in_.fail("no $MeshFormat section: not an MSH file");
    if (!haveNodes) in_.fail("no $Nodes section");
    if (!haveElements) in_.fail("no $Elements section");
    finish();
    return std::move(result_);
  }

 private:
  // Tokens of the next non-empty line; fails with `what` at the end of the file.
  std::vector<std::string> tokens(const std::string &what) {
    std::string line;
    while (in_.next(line)) {
      auto t = splitWhitespace(line);
      if (t.empty()) continue;
      if (t[0][0] == '$') {
        in_.fail("expected " + what + ", found '" + t[0] + "'");
      }
      return t;
    }
    in_.fail("file ends inside a section: expected " + what);
  }

  std::int64_t integer(const std::string &token, const char *what) {
    std::int64_t v = 0;
    if (!parseInt(token, v)) in_.fail(std::string("bad ") + what + " '" + token + "'");
    return v;
  }

  std::int64_t count(const std::string &token, const char *what) {
    const std::int64_t v = integer(token, what);
    if (v < 0) in_.fail(std::string("negative ") + what + " " + token);
    return v;
  }

  void expectEnd(const std::string &section) {
    std::string line;
    while (in_.next(line)) {
      const std::string t = trim(line);
      if (t.empty()) continue;
      if (t == "$End" + section) return;
      in_.fail("expected $End" + section + ", found '" + t + "'");
    }
    in_.fail("missing $End" + section);
  }

  void skipSection(const std::string &section) {
    std::string line;
    while (in_.next(line)) {
      const std::string t = trim(line);
      if (t == "$End" + section) return;
      if (!t.empty() && t[0] == '$' && t.rfind("$End", 0) != 0) {
        in_.fail("missing $End" + section + " before " + t);
      }
    }
    in_.fail("missing $End" + section);
  }

  void readFormat() {
    const auto t = tokens("'version file-type data-size'");
    if (t.size() != 3) in_.fail("expected 'version file-type data-size'");
    if (t[0] != "4.1") in_.fail("MSH version " + t[0] + " is not supported; save as MSH 4.1 ASCII");
    if (t[1] != "0") in_.fail("binary MSH files are not supported; save as MSH 4.1 ASCII");
    expectEnd("MeshFormat");
  }

  void readPhysicalNames() {
    const auto header = tokens("the number of physical names");
    const std::int64_t n = count(header[0], "number of physical names");
    for (std::int64_t i = 0; i < n; ++i) {
      std::string line;
      const auto t = tokens("'dim tag \"name\"'");
      if (t.size() < 3) in_.fail("expected 'dim tag \"name\"'");
      const std::int64_t dim = integer(t[0], "dimension"), tag = integer(t[1], "physical tag");
      if (dim < 0 || dim > 3) in_.fail("physical dimension " + t[0] + " outside 0..3");
      // The name is quoted and may contain blanks: take it from the raw line.
      in_.unread();
      in_.next(line);
      const std::size_t open = line.find('"'), close = line.rfind('"');
      if (open == std::string::npos || close == open) in_.fail("physical name must be quoted");
      physicalNames_[{dim, tag}] = line.substr(open + 1, close - open - 1);
    }
    expectEnd("PhysicalNames");
  }

  void readEntities() {
    const auto header = tokens("'numPoints numCurves numSurfaces numVolumes'");
    if (header.size() != 4) in_.fail("expected 'numPoints numCurves numSurfaces numVolumes'");
    for (int dim = 0; dim < 4; ++dim) {
      const std::int64_t n = count(header[static_cast<std::size_t>(dim)], "number of entities");
      for (std::int64_t i = 0; i < n; ++i) {
        const auto t = tokens("an entity");
        // Points: tag x y z; others: tag and a bounding box of six numbers.
        const std::size_t physAt = dim == 0 ? 4 : 7;
        if (t.size() < physAt + 1) in_.fail("truncated entity line");
        const std::int64_t tag = integer(t[0], "entity tag");
        for (std::size_t k = 1; k < physAt; ++k) {
          double x;
          if (!parseDouble(t[k], x)) in_.fail("bad coordinate '" + t[k] + "'");
        }
        const std::int64_t np = count(t[physAt], "number of physical tags");
        if (t.size() < physAt + 1 + static_cast<std::size_t>(np)) in_.fail("truncated entity line");
        std::vector<std::int64_t> tags;
        for (std::int64_t p = 0; p < np; ++p) {
          // Gmsh writes negative physical tags for groups with reversed orientation.
          const std::int64_t pt = integer(t[physAt + 1 + static_cast<std::size_t>(p)], "physical tag");
          tags.push_back(pt < 0 ? -pt : pt);
        }
        if (!entityPhysicals_.emplace(std::make_pair(std::int64_t(dim), tag), tags).second) {
          in_.fail("entity " + std::to_string(dim) + "d " + std::to_string(tag) + " defined twice");
        }
      }
    }
    expectEnd("Entities");
  }

  void readNodes() {
    const auto header = tokens("'numEntityBlocks numNodes minNodeTag maxNodeTag'");
    if (header.size() != 4) in_.fail("expected 'numEntityBlocks numNodes minNodeTag maxNodeTag'");
    // The header's node total is not checked: Gmsh 4.8 itself writes totals that differ from
    // its blocks when it re-saves meshes with point entities; the blocks are read exactly.
    const std::int64_t blocks = count(header[0], "number of blocks");
    count(header[1], "number of nodes");
    for (std::int64_t b = 0; b < blocks; ++b) {
      const auto t = tokens("'entityDim entityTag parametric numNodesInBlock'");
      if (t.size() != 4) in_.fail("expected 'entityDim entityTag parametric numNodesInBlock'");
      const std::int64_t n = count(t[3], "number of nodes in block");
      std::vector<std::int64_t> tags;
      for (std::int64_t i = 0; i < n; ++i) {
        const auto tt = tokens("a node tag");
        if (tt.size() != 1) in_.fail("expected one node tag per line");
        const std::int64_t tag = integer(tt[0], "node tag");
        if (!nodeLine_.emplace(tag, in_.lineNumber()).second) in_.fail("duplicate node tag " + tt[0]);
        tags.push_back(tag);
      }
      for (std::int64_t i = 0; i < n; ++i) {
        const auto xt = tokens("node coordinates");
        if (xt.size() < 3) in_.fail("expected 'x y z' (and parametric coordinates)");
        Eigen::Vector3d x;
        for (int k = 0; k < 3; ++k) {
          if (!parseDouble(xt[static_cast<std::size_t>(k)], x[k])) {
            in_.fail("bad coordinate '" + xt[static_cast<std::size_t>(k)] + "'");
          }
        }
        result_.nodeFileIds.push_back(tags[static_cast<std::size_t>(i)]);
        result_.mesh.nodes.push_back(x);
      }
    }
    expectEnd("Nodes");
    result_.indexFileIds();
  }

  NodeId node(const std::string &token, std::int64_t element) {
    const std::int64_t tag = integer(token, "node tag");
    if (!result_.hasNodeFileId(tag)) {
      in_.fail("element " + std::to_string(element) + " refers to node " + token +
               ", which $Nodes does not define");
    }
    return result_.nodeOfFileId(tag);
  }

  void readElements() {
    const auto header = tokens("'numEntityBlocks numElements minElementTag maxElementTag'");
    if (header.size() != 4) in_.fail("expected 'numEntityBlocks numElements minElementTag maxElementTag'");
    const std::int64_t blocks = count(header[0], "number of blocks"),
                       total = count(header[1], "number of elements");
    std::int64_t seen = 0;
    std::set<std::int64_t> tags;
    for (std::int64_t b = 0; b < blocks; ++b) {
      const auto t = tokens("'entityDim entityTag elementType numElementsInBlock'");
      if (t.size() != 4) in_.fail("expected 'entityDim entityTag elementType numElementsInBlock'");
      const std::int64_t dim = integer(t[0], "entity dimension"), entity = integer(t[1], "entity tag");
      const std::int64_t type = integer(t[2], "element type"), n = count(t[3], "number of elements in block");
      if (dim < 0 || dim > 3) in_.fail("entity dimension " + t[0] + " outside 0..3");
      const auto physicals = entityPhysicals_.find({dim, entity});
      if (!entityPhysicals_.empty() && physicals == entityPhysicals_.end()) {
        in_.fail("element block of entity " + t[0] + "d " + t[1] + ", which $Entities does not define");
      }
      const bool grouped = physicals != entityPhysicals_.end() && !physicals->second.empty();
      const bool mapped = type == kMappedType[dim];
      if (!mapped && (dim == 3 || grouped)) {
        in_.fail("element " + typeName(type) + " in " + (dim == 3 ? "volume" : "grouped") + " entity " +
                 t[1] +
                 ": Glossa reads 8-node hexahedra (type 5) in volumes and 4-node quadrangles (type 3), "
                 "2-node lines (type 1) and points (type 15) in physical groups");
      }
      const auto known = kTypes.find(type);
      const int nn = known == kTypes.end() ? -1 : known->second.nodes;
      for (std::int64_t i = 0; i < n; ++i) {
        const auto et = tokens("an element");
        const std::int64_t tag = integer(et[0], "element tag");
        if (!tags.insert(tag).second) in_.fail("duplicate element tag " + et[0]);
        ++seen;
        if (!mapped) continue;  // an unused element of an ungrouped lower-dimensional entity
        if (static_cast<int>(et.size()) != 1 + nn) {
          in_.fail("element " + et[0] + " of " + typeName(type) + " needs " + std::to_string(nn) +
                   " nodes, found " + std::to_string(et.size() - 1));
        }
        std::vector<NodeId> nodes;
        for (int a = 0; a < nn; ++a) nodes.push_back(node(et[static_cast<std::size_t>(1 + a)], tag));
        if (dim == 3) {
          Hex hex;
          std::copy(nodes.begin(), nodes.end(), hex.begin());  // Gmsh order = VTK order
          result_.mesh.elements.push_back(hex);
          result_.elementFileIds.push_back(tag);
          elementLines_.push_back(in_.lineNumber());
          for (std::int64_t p :
               physicals == entityPhysicals_.end() ? std::vector<std::int64_t>{} : physicals->second) {
            volumeMembers_[p].push_back(static_cast<ElementId>(result_.mesh.elements.size() - 1));
          }
        } else if (grouped) {
          for (std::int64_t p : physicals->second) {
            if (dim == 2) {
              std::array<NodeId, 4> quad{nodes[0], nodes[1], nodes[2], nodes[3]};
              surfaceMembers_[p].push_back({quad, in_.lineNumber(), tag});
            } else {
              lowerMembers_[{dim, p}].insert(lowerMembers_[{dim, p}].end(), nodes.begin(), nodes.end());
            }
          }
        }
      }
    }
    if (seen != total) {
      in_.fail("$Elements header announces " + std::to_string(total) + " elements, the blocks hold " +
               std::to_string(seen));
    }
    expectEnd("Elements");
  }

  std::string groupName(std::int64_t dim, std::int64_t tag) const {
    const auto it = physicalNames_.find({dim, tag});
    if (it != physicalNames_.end()) return it->second;
    return "physical" + std::to_string(dim) + "d_" + std::to_string(tag);
  }

  void finish() {
    HexMesh &mesh = result_.mesh;
    if (mesh.elements.empty()) in_.fail("no 8-node hexahedra (type 5) in the file");
    result_.indexFileIds();
    importing::checkElements(mesh, result_.source, elementLines_, result_.elementFileIds);
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
          importing::fail(result_.source, q.line,
                          "quadrangle " + std::to_string(q.tag) + " of physical surface '" + name +
                              "' is not a face of any hexahedron");
        }
        faces.push_back(face);
        nodes.insert(nodes.end(), q.nodes.begin(), q.nodes.end());
      }
      importing::sortUnique(faces);
      importing::sortUnique(nodes);
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
  }

  struct Quad {
    std::array<NodeId, 4> nodes;
    std::size_t line;
    std::int64_t tag;
  };

  LineReader in_;
  ImportedMesh result_;
  std::map<std::pair<std::int64_t, std::int64_t>, std::string> physicalNames_;  // (dim, tag)
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::int64_t>> entityPhysicals_;
  std::map<std::int64_t, std::size_t> nodeLine_;
  std::vector<std::size_t> elementLines_;
  std::map<std::int64_t, std::vector<ElementId>> volumeMembers_;
  std::map<std::int64_t, std::vector<Quad>> surfaceMembers_;
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<NodeId>> lowerMembers_;
};

}  // namespace

ImportedMesh readGmsh(const std::string &file) { return GmshParser(file).parse(); }

}  // namespace glossa::mesh
