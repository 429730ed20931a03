#include "mesh/AbaqusReader.hpp"

#include <map>
#include <regex>
#include <set>
#include <stdexcept>

#include "mesh/ImportSupport.hpp"

namespace glossa::mesh {

using importing::LineReader;
using importing::parseDouble;
using importing::parseInt;
using importing::splitCommas;
using importing::trim;
using importing::upper;

namespace {

const std::set<std::string> kHexTypes = {"C3D8", "C3D8H", "C3D8R", "C3D8RH"};
const std::set<std::string> kQuadTypes = {"CPS4", "CPS4R", "CPE4",  "CPE4R",  "S4",     "S4R",
                                          "R3D4", "M3D4",  "M3D4R", "SFM3D4", "SFM3D4R"};
// 2-node lines: Gmsh exports a physical curve as T3D2 elements in an ELSET; like MSH's physical
// curves they give node sets.
const std::set<std::string> kLineTypes = {"T3D2", "T2D2", "B31", "B21"};

const char *kSubdivide = "'Mesh.SubdivisionAlgorithm = 2;' in Gmsh (every element split into hexahedra)";

// What to do about an element type Glossa does not read, as the MSH reader says it for Gmsh's
// types: from the node count of the Abaqus name (C3D4, CPS3, C3D20R, S8R, ...); "" if unknown.
std::string remedyFor(const std::string &type) {
  static const std::regex solid(R"(C3D(\d{1,3})\D*)"), facet(R"((CPS|CPE|CAX|S|R3D|M3D|SFM3D)(\d{1,3})\D*)");
  std::smatch m;
  const bool isSolid = std::regex_match(type, m, solid);
  if (!isSolid && !std::regex_match(type, m, facet)) return "";
  const int nodes = std::stoi(m[isSolid ? 1 : 2].str());
  if (isSolid && (nodes == 4 || nodes == 10))
    return "tetrahedra: Glossa needs hexahedra; mesh the volume with hexahedra (in Gmsh a transfinite, recombined "
           "volume, or an extrusion of recombined surfaces), or " + std::string(kSubdivide);
  if (isSolid && (nodes == 6 || nodes == 15))
    return "prisms: Glossa needs hexahedra; recombine the surface before extruding it, or " + std::string(kSubdivide);
  if (isSolid && nodes == 5)
    return "pyramids: Glossa needs hexahedra; make the whole volume transfinite and recombined, or " +
           std::string(kSubdivide);
  if (isSolid && (nodes == 20 || nodes == 27))
    return "second-order hexahedra: Glossa reads 8-node ones; export first-order elements (Gmsh 'Mesh.ElementOrder = "
           "1;', Abaqus/CAE geometric order Linear)";
  if (nodes == 3 || nodes == 6)
    return "triangles: a face set is made of hexahedron faces, 4-node quadrilaterals; 'Recombine Surface', or " +
           std::string(kSubdivide);
  if (nodes == 8 || nodes == 9)
    return "second-order quadrilaterals: Glossa reads 4-node ones; export first-order elements (Gmsh "
           "'Mesh.ElementOrder = 1;', Abaqus/CAE geometric order Linear)";
  return "";
}

struct Keyword {
  std::string name;                           // upper case, without '*'
  std::map<std::string, std::string> params;  // upper-case keys; values as written
  std::size_t line;
};

// A set as defined in the file: members by file id, the line that defined it first.
struct FileSet {
  std::string name;  // as first written
  std::vector<std::int64_t> ids;
  std::size_t line;
};

struct FileElement {
  std::vector<std::int64_t> nodes;
  std::size_t line;
  bool hex;
  bool segment;  // a 2-node line (neither hexahedron nor quadrilateral)
};

class AbaqusParser {
 public:
  explicit AbaqusParser(const std::string &file) : in_(file) { result_.source = file; }

  ImportedMesh parse() {
    Keyword keyword;
    bool haveKeyword = false;
    std::string line;
    while (in_.next(line)) {
      const std::string t = trim(line);
      if (t.empty() || t.rfind("**", 0) == 0) continue;
      if (t[0] == '*') {
        if (haveKeyword) endKeyword(keyword);
        keyword = readKeyword(t);
        haveKeyword = true;
        beginKeyword(keyword);
        continue;
      }
      if (!haveKeyword) in_.fail("data line before any keyword");
      dataLine(keyword, t);
    }
    if (haveKeyword) endKeyword(keyword);
    return finish();
  }

 private:
  Keyword readKeyword(std::string text) {
    // A keyword line ending in a comma continues on the next line.
    std::string more;
    while (!text.empty() && text.back() == ',' && in_.next(more)) text += trim(more);
    const auto fields = splitCommas(text);
    Keyword k;
    k.line = in_.lineNumber();
    std::string name = upper(fields[0].substr(1));
    // "*End Part" and "*END PART" are one keyword: collapse blanks.
    std::string collapsed;
    for (char c : name) {
      if (c == ' ' || c == '\t') {
        if (!collapsed.empty() && collapsed.back() != ' ') collapsed += ' ';
      } else {
        collapsed += c;
      }
    }
    k.name = trim(collapsed);
    for (std::size_t i = 1; i < fields.size(); ++i) {
      if (fields[i].empty()) continue;
      const std::size_t eq = fields[i].find('=');
      const std::string key = upper(trim(fields[i].substr(0, eq)));
      k.params[key] = eq == std::string::npos ? "" : trim(fields[i].substr(eq + 1));
    }
    return k;
  }

  std::string param(const Keyword &k, const std::string &key) {
    const auto it = k.params.find(key);
    if (it == k.params.end() || it->second.empty()) in_.fail("*" + k.name + " needs " + key + "=");
    return it->second;
  }

  std::int64_t integer(const std::string &token, const std::string &what) {
    std::int64_t v = 0;
    if (!parseInt(token, v)) in_.fail("bad " + what + " '" + token + "'");
    return v;
  }

  // Fields of a data line without the empty one a trailing comma leaves.
  std::vector<std::string> fields(const std::string &line) {
    auto f = splitCommas(line);
    while (!f.empty() && f.back().empty()) f.pop_back();
    for (const auto &x : f) {
      if (x.empty()) in_.fail("empty field");
    }
    return f;
  }

  FileSet &set(std::map<std::string, FileSet> &sets, const std::string &name) {
    FileSet &s = sets[upper(name)];  // Abaqus set names are case-insensitive
    if (s.name.empty()) {
      s.name = name;
      s.line = in_.lineNumber();
    }
    return s;
  }

  void beginKeyword(const Keyword &k) {
    pending_.clear();
    if (k.name == "NODE") {
      if (k.params.count("NSET")) set(nsets_, param(k, "NSET"));
    } else if (k.name == "ELEMENT") {
      const std::string type = upper(param(k, "TYPE"));
      if (!kHexTypes.count(type) && !kQuadTypes.count(type) && !kLineTypes.count(type)) {
        const std::string remedy = remedyFor(type);
        in_.fail("element type " + type +
                 " is not supported: Glossa reads C3D8, C3D8H, C3D8R and C3D8RH hexahedra, 4-node "
                 "quadrilaterals (CPS4, S4, R3D4, ...) as face sets and 2-node lines (T3D2, T2D2, B31, B21) "
                 "as node sets" + (remedy.empty() ? "" : ". " + type + " are " + remedy));
      }
      if (k.params.count("ELSET")) set(elsets_, param(k, "ELSET"));
    } else if (k.name == "ELSET") {
      set(elsets_, param(k, "ELSET"));
    } else if (k.name == "NSET") {
      set(nsets_, param(k, "NSET"));
    } else if (k.name == "SURFACE") {
      const std::string type = k.params.count("TYPE") ? upper(k.params.at("TYPE")) : "ELEMENT";
      if (type != "ELEMENT") in_.fail("*SURFACE, TYPE=" + type + " is not supported (TYPE=ELEMENT only)");
      const std::string name = param(k, "NAME");
      if (surfaces_.count(upper(name))) in_.fail("surface '" + name + "' defined twice");
      surfaces_[upper(name)] = {name, {}, k.line};
    } else if (k.name == "INCLUDE") {
      in_.fail("*INCLUDE is not supported; merge the included file");
    } else if (k.name == "PART") {
      if (++parts_ > 1) in_.fail("a second *PART: only single-part (flat) input files are supported");
    }
  }

  void dataLine(const Keyword &k, const std::string &line) {
    if (k.name == "NODE") {
      const auto f = fields(line);
      if (f.size() < 4 || f.size() > 7) in_.fail("expected 'id, x, y, z' in *NODE");
      const std::int64_t id = integer(f[0], "node id");
      Eigen::Vector3d x;
      for (int i = 0; i < 3; ++i) {
        if (!parseDouble(f[static_cast<std::size_t>(i + 1)], x[i])) {
          in_.fail("bad coordinate '" + f[static_cast<std::size_t>(i + 1)] + "'");
        }
      }
      if (!nodeIds_.insert(id).second) in_.fail("duplicate node id " + f[0]);
      result_.nodeFileIds.push_back(id);
      result_.mesh.nodes.push_back(x);
      if (k.params.count("NSET")) set(nsets_, k.params.at("NSET")).ids.push_back(id);
    } else if (k.name == "ELEMENT") {
      const bool hex = kHexTypes.count(upper(k.params.at("TYPE"))) != 0;
      const bool segment = kLineTypes.count(upper(k.params.at("TYPE"))) != 0;
      const std::size_t needed = hex ? 9 : segment ? 3 : 5;
      if (pending_.empty()) pendingLine_ = in_.lineNumber();
      for (const auto &x : fields(line)) pending_.push_back(x);
      if (pending_.size() > needed) {
        in_.fail("element " + pending_[0] + " of type " + upper(k.params.at("TYPE")) + " needs " +
                 std::to_string(needed - 1) + " nodes, found " + std::to_string(pending_.size() - 1));
      }
      if (pending_.size() < needed) return;  // continued on the next line
      const std::int64_t id = integer(pending_[0], "element id");
      if (elements_.count(id)) in_.fail("duplicate element id " + pending_[0]);
      FileElement e{{}, pendingLine_, hex, segment};
      for (std::size_t a = 1; a < needed; ++a) e.nodes.push_back(integer(pending_[a], "node id"));
      elements_[id] = e;
      elementOrder_.push_back(id);
      if (k.params.count("ELSET")) set(elsets_, k.params.at("ELSET")).ids.push_back(id);
      pending_.clear();
    } else if (k.name == "ELSET" || k.name == "NSET") {
      const bool elset = k.name == "ELSET";
      auto &sets = elset ? elsets_ : nsets_;
      FileSet &s = set(sets, param(k, elset ? "ELSET" : "NSET"));
      const auto f = fields(line);
      if (k.params.count("GENERATE")) {
        if (f.size() < 2 || f.size() > 3) in_.fail("expected 'first, last[, step]' with GENERATE");
        const std::int64_t a = integer(f[0], "id"), b = integer(f[1], "id");
        const std::int64_t step = f.size() == 3 ? integer(f[2], "step") : 1;
        if (step < 1 || b < a) in_.fail("GENERATE needs first <= last and a positive step");
        // The range may only name ids defined above: '1, 2147483648' would otherwise fill memory
        // with ids no node has (found by the fuzz test) before the unknown id is reported.
        const std::int64_t largest = elset ? (elements_.empty() ? 0 : elements_.rbegin()->first)
                                           : (nodeIds_.empty() ? 0 : *nodeIds_.rbegin());
        if (b > largest)
          in_.fail("GENERATE range " + f[0] + " to " + f[1] + " reaches past the largest " +
                   (elset ? "element" : "node") + " id defined above it (" + std::to_string(largest) + ")");
        for (std::int64_t id = a; id <= b; id += step) s.ids.push_back(id);
        return;
      }
      for (const auto &x : f) {
        std::int64_t id = 0;
        if (parseInt(x, id)) {
          s.ids.push_back(id);
          continue;
        }
        const auto other = sets.find(upper(x));
        if (other == sets.end())
          in_.fail("unknown " + std::string(elset ? "element" : "node") + " set '" + x + "'");
        // A set can only hold sets defined above it; naming itself would add nothing (or its
        // own entries again) and is a mistake in the file.
        if (&other->second == &s) in_.fail(std::string(elset ? "element" : "node") + " set '" + s.name + "' names itself");
        s.ids.insert(s.ids.end(), other->second.ids.begin(), other->second.ids.end());
      }
    } else if (k.name == "SURFACE") {
      const auto f = fields(line);
      if (f.size() != 2) in_.fail("expected 'element or element set, S1..S6' in *SURFACE");
      const std::string face = upper(f[1]);
      if (face.size() != 2 || face[0] != 'S' || face[1] < '1' || face[1] > '6') {
        in_.fail("face identifier '" + f[1] + "' is not S1..S6 (hexahedron faces)");
      }
      const int localFace = face[1] - '1';  // Sk = Glossa face k-1 (see the header)
      std::vector<std::int64_t> ids;
      std::int64_t id = 0;
      if (parseInt(f[0], id)) {
        ids.push_back(id);
      } else {
        const auto s = elsets_.find(upper(f[0]));
        if (s == elsets_.end()) in_.fail("unknown element set '" + f[0] + "'");
        ids = s->second.ids;
      }
      for (std::int64_t e : ids)
        surfaceFaces_[upper(param(k, "NAME"))].push_back({e, localFace, in_.lineNumber()});
    } else if (k.name == "INSTANCE") {
      in_.fail("positioned *INSTANCE (translation/rotation lines) is not supported");
    }
    // Data of other keywords (materials, steps, ...) is not mesh data.
  }

  void endKeyword(const Keyword &k) {
    if (k.name == "ELEMENT" && !pending_.empty()) {
      importing::fail(result_.source, pendingLine_, "element " + pending_[0] + " is truncated");
    }
  }

  ImportedMesh finish() {
    HexMesh &mesh = result_.mesh;
    result_.indexFileIds();
    std::vector<std::size_t> lines;
    for (std::int64_t id : elementOrder_) {
      const FileElement &e = elements_.at(id);
      for (std::int64_t n : e.nodes) {
        if (!result_.hasNodeFileId(n)) {
          importing::fail(result_.source, e.line,
                          "element " + std::to_string(id) + " refers to node " + std::to_string(n) +
                              ", which no *NODE defines");
        }
      }
      if (!e.hex) continue;
      Hex hex;
      for (int a = 0; a < 8; ++a) hex[a] = result_.nodeOfFileId(e.nodes[static_cast<std::size_t>(a)]);
      mesh.elements.push_back(hex);  // Abaqus C3D8 order = VTK order
      result_.elementFileIds.push_back(id);
      lines.push_back(e.line);
    }
    if (mesh.elements.empty()) in_.fail("no hexahedral elements (C3D8, C3D8H, C3D8R, C3D8RH)");
    result_.indexFileIds();
    importing::checkElements(mesh, result_.source, lines, result_.elementFileIds);

    const importing::FaceLocator locator(mesh);
    for (const auto &[key, s] : elsets_) {
      // An empty set would become a tissue, fibre family or face set of nothing.
      if (s.ids.empty())
        importing::fail(result_.source, s.line, "element set '" + s.name + "' is empty; give it elements or remove it");
      std::vector<ElementId> hexes;
      std::vector<ElementFace> faces;
      std::vector<NodeId> lineNodes;
      for (std::int64_t id : s.ids) {
        const auto it = elements_.find(id);
        if (it == elements_.end()) {
          importing::fail(result_.source, s.line,
                          "element set '" + s.name + "' refers to element " + std::to_string(id) +
                              ", which no *ELEMENT defines");
        }
        if (it->second.hex) {
          hexes.push_back(result_.elementOfFileId(id));
          continue;
        }
        if (it->second.segment) {
          for (std::int64_t n : it->second.nodes) lineNodes.push_back(result_.nodeOfFileId(n));
          continue;
        }
        std::array<NodeId, 4> quad;
        for (int a = 0; a < 4; ++a)
          quad[a] = result_.nodeOfFileId(it->second.nodes[static_cast<std::size_t>(a)]);
        ElementFace face;
        if (!locator.find(quad, face)) {
          importing::fail(result_.source, it->second.line,
                          "quadrilateral " + std::to_string(id) + " of element set '" + s.name +
                              "' is not a face of any hexahedron");
        }
        faces.push_back(face);
      }
      if (int(!hexes.empty()) + int(!faces.empty()) + int(!lineNodes.empty()) > 1) {
        importing::fail(result_.source, s.line,
                        "element set '" + s.name + "' mixes hexahedra, quadrilaterals and lines");
      }
      if (!lineNodes.empty()) {
        importing::sortUnique(lineNodes);
        mesh.nodeSets[s.name] = lineNodes;  // an NSET of the same name, below, takes precedence
      } else if (faces.empty()) {
        importing::sortUnique(hexes);
        mesh.elementSets[s.name] = hexes;
      } else {
        addFaceSet(s.name, faces);
      }
    }
    for (const auto &[key, s] : surfaces_) {
      std::vector<ElementFace> faces;
      for (const SurfaceFace &f : surfaceFaces_[key]) {
        const auto it = elements_.find(f.element);
        if (it == elements_.end() || !it->second.hex) {
          importing::fail(result_.source, f.line,
                          "surface '" + s.name + "' refers to element " + std::to_string(f.element) +
                              ", which is not a hexahedron");
        }
        faces.push_back({result_.elementOfFileId(f.element), f.localFace});
      }
      addFaceSet(s.name, faces);
    }
    for (const auto &[key, s] : nsets_) {
      std::vector<NodeId> nodes;
      for (std::int64_t id : s.ids) {
        if (!result_.hasNodeFileId(id)) {
          importing::fail(
              result_.source, s.line,
              "node set '" + s.name + "' refers to node " + std::to_string(id) + ", which no *NODE defines");
        }
        nodes.push_back(result_.nodeOfFileId(id));
      }
      importing::sortUnique(nodes);
      mesh.nodeSets[s.name] = nodes;
    }
    // Node sets of face sets, unless an NSET already has the name.
    for (const auto &[name, faces] : mesh.faceSets) {
      bool named = false;
      for (const auto &[key, s] : nsets_) named = named || upper(name) == key;
      if (!named) mesh.nodeSets[name] = mesh.nodesOfFaceSet(name);
    }
    return std::move(result_);
  }

  void addFaceSet(const std::string &name, std::vector<ElementFace> faces) {
    importing::sortUnique(faces);
    auto &set = result_.mesh.faceSets[name];
    set.insert(set.end(), faces.begin(), faces.end());
    importing::sortUnique(set);
  }

  struct SurfaceFace {
    std::int64_t element;
    int localFace;
    std::size_t line;
  };

  LineReader in_;
  ImportedMesh result_;
  std::set<std::int64_t> nodeIds_;
  std::map<std::int64_t, FileElement> elements_;
  std::vector<std::int64_t> elementOrder_;
  std::map<std::string, FileSet> elsets_, nsets_, surfaces_;  // keyed by upper-case name
  std::map<std::string, std::vector<SurfaceFace>> surfaceFaces_;
  std::vector<std::string> pending_;  // fields of an element continued over lines
  std::size_t pendingLine_ = 0;
  int parts_ = 0;
};

}  // namespace

ImportedMesh readAbaqus(const std::string &file) { return AbaqusParser(file).parse(); }

}  // namespace glossa::mesh
