// ASCII MSH, versions 4.1 and 2.2: sections read line by line, errors as "file:line: reason".

#include <map>
#include <vector>

#include "mesh/GmshAssembly.hpp"
#include "mesh/GmshParsers.hpp"
#include "mesh/ImportSupport.hpp"

namespace glossa::mesh::gmsh {

using importing::LineReader;
using importing::parseDouble;
using importing::parseInt;
using importing::splitWhitespace;
using importing::trim;

namespace {

class AsciiParser {
 public:
  explicit AsciiParser(const std::string &file) : in_(file), assembly_(file) {}

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
      } else if (section == "Entities" && !msh2_) {
        readEntities();
      } else if (section == "PartitionedEntities") {
        in_.fail("partitioned MSH files are not supported; save the mesh unpartitioned");
      } else if (section == "Nodes") {
        msh2_ ? readNodes2() : readNodes4();
        haveNodes = true;
      } else if (section == "Elements") {
        if (!haveNodes) in_.fail("$Elements before $Nodes");
        msh2_ ? readElements2() : readElements4();
        haveElements = true;
      } else {
        skipSection(section);
      }
    }
    if (!haveFormat) in_.fail("no $MeshFormat section: not an MSH file");
    if (!haveNodes) in_.fail("no $Nodes section");
    if (!haveElements) in_.fail("no $Elements section");
    return assembly_.finish(here());
  }

 private:
  Place here() const { return Place::atLine(in_.lineNumber()); }

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

  Eigen::Vector3d point(const std::vector<std::string> &t, std::size_t first) {
    Eigen::Vector3d x;
    for (int k = 0; k < 3; ++k) {
      const std::string &token = t[first + static_cast<std::size_t>(k)];
      if (!parseDouble(token, x[k])) in_.fail("bad coordinate '" + token + "'");
    }
    return x;
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
    if (t[0] != "4.1" && t[0] != "2.2") {
      in_.fail(
          "MSH version " + t[0] +
          " is not supported; Glossa reads MSH 4.1 and 2.2, ASCII or binary (gmsh -format msh41 or msh22)");
    }
    // A binary file is dispatched to the binary parser before this one; a file that says
    // binary here has binary bytes that the line reader has already split.
    if (t[1] != "0") in_.fail("file-type " + t[1] + " is not ASCII (0)");
    msh2_ = t[0] == "2.2";
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
      assembly_.physicalName(static_cast<int>(dim), tag, line.substr(open + 1, close - open - 1));
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

  void readNodes4() {
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
      std::vector<std::size_t> lines;
      for (std::int64_t i = 0; i < n; ++i) {
        const auto tt = tokens("a node tag");
        if (tt.size() != 1) in_.fail("expected one node tag per line");
        tags.push_back(integer(tt[0], "node tag"));
        lines.push_back(in_.lineNumber());
      }
      for (std::int64_t i = 0; i < n; ++i) {
        const auto xt = tokens("node coordinates");
        if (xt.size() < 3) in_.fail("expected 'x y z' (and parametric coordinates)");
        const auto k = static_cast<std::size_t>(i);
        assembly_.node(tags[k], point(xt, 0), Place::atLine(lines[k]));
      }
    }
    expectEnd("Nodes");
  }

  void readElements4() {
    const auto header = tokens("'numEntityBlocks numElements minElementTag maxElementTag'");
    if (header.size() != 4) in_.fail("expected 'numEntityBlocks numElements minElementTag maxElementTag'");
    const std::int64_t blocks = count(header[0], "number of blocks"),
                       total = count(header[1], "number of elements");
    std::int64_t seen = 0;
    const std::vector<std::int64_t> none;
    for (std::int64_t b = 0; b < blocks; ++b) {
      const auto t = tokens("'entityDim entityTag elementType numElementsInBlock'");
      if (t.size() != 4) in_.fail("expected 'entityDim entityTag elementType numElementsInBlock'");
      const std::int64_t dim = integer(t[0], "entity dimension"), entity = integer(t[1], "entity tag");
      const std::int64_t type = integer(t[2], "element type"), n = count(t[3], "number of elements in block");
      if (dim < 0 || dim > 3) in_.fail("entity dimension " + t[0] + " outside 0..3");
      const auto found = entityPhysicals_.find({dim, entity});
      if (!entityPhysicals_.empty() && found == entityPhysicals_.end()) {
        in_.fail("element block of entity " + t[0] + "d " + t[1] + ", which $Entities does not define");
      }
      const std::vector<std::int64_t> &physicals = found == entityPhysicals_.end() ? none : found->second;
      const int d = static_cast<int>(dim);
      const bool read = assembly_.accepts(
          d, type, !physicals.empty(), [&] { return assembly_.entityName(d, entity, physicals); }, here());
      for (std::int64_t i = 0; i < n; ++i) {
        const auto et = tokens("an element");
        const std::int64_t tag = integer(et[0], "element tag");
        assembly_.elementTag(tag, here());
        ++seen;
        if (!read) continue;  // an unused element of an ungrouped lower-dimensional entity
        std::vector<std::int64_t> nodes;
        for (std::size_t a = 1; a < et.size(); ++a) nodes.push_back(integer(et[a], "node tag"));
        assembly_.element(d, type, tag, entity, nodes, physicals, here());
      }
    }
    if (seen != total) {
      in_.fail("$Elements header announces " + std::to_string(total) + " elements, the blocks hold " +
               std::to_string(seen));
    }
    expectEnd("Elements");
  }

  // MSH 2.2: "$Nodes", a count, then "id x y z" lines.
  void readNodes2() {
    const auto header = tokens("the number of nodes");
    if (header.size() != 1) in_.fail("expected the number of nodes");
    const std::int64_t n = count(header[0], "number of nodes");
    for (std::int64_t i = 0; i < n; ++i) {
      const auto t = tokens("'id x y z'");
      if (t.size() != 4) in_.fail("expected 'id x y z'");
      assembly_.node(integer(t[0], "node tag"), point(t, 1), here());
    }
    expectEnd("Nodes");
  }

  // MSH 2.2: "$Elements", a count, then "id type ntags tag... node..." lines. The first tag is
  // the physical group (0: none), the second the elementary entity; later ones (partitions) are
  // not needed.
  void readElements2() {
    const auto header = tokens("the number of elements");
    if (header.size() != 1) in_.fail("expected the number of elements");
    const std::int64_t n = count(header[0], "number of elements");
    for (std::int64_t i = 0; i < n; ++i) {
      const auto t = tokens("'id type ntags tags... nodes...'");
      if (t.size() < 3) in_.fail("expected 'id type ntags tags... nodes...'");
      const std::int64_t tag = integer(t[0], "element tag"), type = integer(t[1], "element type");
      const std::int64_t ntags = count(t[2], "number of tags");
      assembly_.elementTag(tag, here());
      const ElementType *known = elementType(type);
      if (!known) in_.fail("element " + t[0] + " has Gmsh type " + t[1] + ", which Glossa does not know");
      if (t.size() < 3 + static_cast<std::size_t>(ntags))
        in_.fail("element " + t[0] + " is truncated in its tags");
      const std::int64_t physical = ntags >= 1 ? integer(t[3], "physical tag") : 0;
      const std::int64_t entity = ntags >= 2 ? integer(t[4], "entity tag") : 0;
      const std::vector<std::int64_t> physicals =
          physical == 0 ? std::vector<std::int64_t>{} : std::vector<std::int64_t>{physical};
      if (!assembly_.accepts(
              known->dim, type, physical != 0,
              [&] { return assembly_.entityName(known->dim, entity, physicals); }, here())) {
        continue;
      }
      std::vector<std::int64_t> nodes;
      for (std::size_t a = 3 + static_cast<std::size_t>(ntags); a < t.size(); ++a) {
        nodes.push_back(integer(t[a], "node tag"));
      }
      assembly_.element(known->dim, type, tag, entity, nodes, physicals, here());
    }
    expectEnd("Elements");
  }

  LineReader in_;
  Assembly assembly_;
  bool msh2_ = false;
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::int64_t>> entityPhysicals_;  // 4.1
};

}  // namespace

ImportedMesh parseAscii(const std::string &file) { return AsciiParser(file).parse(); }

}  // namespace glossa::mesh::gmsh
