// Binary MSH, versions 4.1 and 2.2 (Gmsh reference manual, "MSH file format"). Section headers,
// $PhysicalNames and the 2.2 counts stay ASCII lines; the data between them is raw
// little-endian values. Every count is checked against the bytes left before anything is
// allocated or read, so a truncated or corrupted file gives "file: byte N: reason", never a
// crash or a huge allocation.
//
// 4.1: after "4.1 1 8" an int 1 (the endianness marker). $Entities: size_t numPoints,
// numCurves, numSurfaces, numVolumes; a point is int tag, 3 doubles, size_t numPhysicals, int
// physicals...; a curve, surface or volume is int tag, 6 doubles (bounding box), size_t
// numPhysicals, int physicals..., size_t numBounding, int bounding.... $Nodes: size_t
// numEntityBlocks, numNodes, minTag, maxTag; a block is int entityDim, entityTag, parametric,
// size_t numNodesInBlock, then the size_t tags, then per node 3 doubles (plus entityDim
// parametric ones when parametric is 1). $Elements: size_t numEntityBlocks, numElements, minTag,
// maxTag; a block is int entityDim, entityTag, elementType, size_t numElementsInBlock, then per
// element size_t tag and size_t node tags.
//
// 2.2: after "2.2 1 8" the int 1. $Nodes: an ASCII count line, then per node int id and 3
// doubles. $Elements: an ASCII count line, then blocks of int type, count, ntags, each followed
// by count elements of int id, ntags int tags (physical, entity, ...), the type's int node tags.

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <vector>

#include "mesh/GmshAssembly.hpp"
#include "mesh/GmshParsers.hpp"
#include "mesh/ImportSupport.hpp"

namespace glossa::mesh::gmsh {

using importing::parseInt;
using importing::splitWhitespace;
using importing::trim;

namespace {

class BinaryParser {
 public:
  explicit BinaryParser(const std::string &file) : assembly_(file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) importing::fail(file, 0, "cannot open");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    data_ = buffer.str();
  }

  ImportedMesh parse() {
    readFormat();
    bool haveNodes = false, haveElements = false;
    std::string line;
    while (nextLine(line)) {
      const std::string name = trim(line);
      if (name.empty()) continue;
      if (name[0] != '$')
        fail(lineStart_, "expected a section header ($Name), found '" + shorten(name) + "'");
      const std::string section = name.substr(1);
      if (section == "PhysicalNames") {
        readPhysicalNames();
      } else if (section == "Entities" && !msh2_) {
        readEntities();
      } else if (section == "PartitionedEntities") {
        fail(lineStart_, "partitioned MSH files are not supported; save the mesh unpartitioned");
      } else if (section == "Nodes") {
        msh2_ ? readNodes2() : readNodes4();
        haveNodes = true;
      } else if (section == "Elements") {
        if (!haveNodes) fail(lineStart_, "$Elements before $Nodes");
        msh2_ ? readElements2() : readElements4();
        haveElements = true;
      } else {
        skipSection(section);
      }
    }
    if (!haveNodes) fail(at_, "no $Nodes section");
    if (!haveElements) fail(at_, "no $Elements section");
    return assembly_.finish(Place::atByte(at_));
  }

 private:
  [[noreturn]] void fail(std::size_t byte, const std::string &reason) const {
    assembly_.fail(Place::atByte(byte), reason);
  }

  static std::string shorten(const std::string &s) { return s.size() > 40 ? s.substr(0, 40) + "..." : s; }

  std::size_t left() const { return data_.size() - at_; }

  // The next line (up to '\n', without '\r'); false at the end of the data.
  bool nextLine(std::string &line) {
    if (at_ >= data_.size()) return false;
    lineStart_ = at_;
    std::size_t end = data_.find('\n', at_);
    if (end == std::string::npos) end = data_.size();
    line = data_.substr(at_, end - at_);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    at_ = std::min(end + 1, data_.size());
    return true;
  }

  std::vector<std::string> tokens(const std::string &what) {
    std::string line;
    while (nextLine(line)) {
      auto t = splitWhitespace(line);
      if (t.empty()) continue;
      if (t[0][0] == '$') fail(lineStart_, "expected " + what + ", found '" + shorten(t[0]) + "'");
      return t;
    }
    fail(at_, "file ends inside a section: expected " + what);
  }

  // Refuses `count` items of `size` bytes each when fewer bytes are left (before allocating).
  void need(std::uint64_t count, std::uint64_t size, const std::string &what) const {
    if (size != 0 && count > left() / size) {
      fail(at_, "file ends inside " + what + ": " + std::to_string(count) + " x " + std::to_string(size) +
                    " bytes announced, " + std::to_string(left()) +
                    " left (truncated or corrupted binary file)");
    }
  }

  template <typename T>
  T value(const std::string &what) {
    need(1, sizeof(T), what);
    T v;
    std::memcpy(&v, data_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return v;
  }

  std::int64_t int32(const std::string &what) { return value<std::int32_t>(what); }

  // A size_t count or tag, as a non-negative int64.
  std::int64_t size(const std::string &what) {
    const std::size_t start = at_;
    const std::uint64_t v = value<std::uint64_t>(what);
    if (v > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
      fail(start, what + " " + std::to_string(v) + " is out of range (corrupted binary file?)");
    }
    return static_cast<std::int64_t>(v);
  }

  double real(const std::string &what) {
    const std::size_t start = at_;
    const double v = value<double>(what);
    if (!std::isfinite(v)) fail(start, "non-finite " + what);
    return v;
  }

  // After binary data: the '\n' Gmsh writes after it, then "$End<section>".
  void expectEnd(const std::string &section) {
    std::string line;
    while (nextLine(line)) {
      const std::string t = trim(line);
      if (t.empty()) continue;
      if (t == "$End" + section) return;
      fail(lineStart_,
           "expected $End" + section + " (a count disagrees with the data?), found '" + shorten(t) + "'");
    }
    fail(at_, "missing $End" + section);
  }

  void skipSection(const std::string &section) {
    const std::string end = "\n$End" + section;
    const std::size_t found = data_.find(end, at_ == 0 ? 0 : at_ - 1);
    if (found == std::string::npos) fail(lineStart_, "missing $End" + section);
    at_ = found + 1;
    std::string line;
    nextLine(line);
  }

  void readFormat() {
    std::string line;
    while (nextLine(line) && trim(line).empty()) {
    }
    if (trim(line) != "$MeshFormat") fail(lineStart_, "the file must start with $MeshFormat");
    const auto t = tokens("'version file-type data-size'");
    if (t.size() != 3) fail(lineStart_, "expected 'version file-type data-size'");
    if (t[0] != "4.1" && t[0] != "2.2") {
      fail(lineStart_, "MSH version " + t[0] +
                           " is not supported; Glossa reads MSH 4.1 and 2.2, ASCII or binary (gmsh -format "
                           "msh41 or msh22)");
    }
    if (t[2] != "8") {
      fail(lineStart_,
           "data-size " + t[2] +
               ": Glossa reads binary files with 8-byte sizes (as Gmsh writes on 64-bit machines)");
    }
    msh2_ = t[0] == "2.2";
    const std::size_t markerAt = at_;
    const std::int64_t marker = int32("the endianness marker");
    if (marker != 1) {
      fail(markerAt,
           marker == 0x01000000
               ? std::string("the endianness marker reads 16777216, not 1: the file was written big-endian, "
                             "which Glossa does not read; save it on this machine or as ASCII")
               : "bad endianness marker " + std::to_string(marker) + " (expected the int 1)");
    }
    expectEnd("MeshFormat");
  }

  void readPhysicalNames() {
    const auto header = tokens("the number of physical names");
    std::int64_t n = 0;
    if (!parseInt(header[0], n) || n < 0)
      fail(lineStart_, "bad number of physical names '" + header[0] + "'");
    std::string line;
    for (std::int64_t i = 0; i < n; ++i) {
      const auto t = tokens("'dim tag \"name\"'");
      std::int64_t dim = 0, tag = 0;
      if (t.size() < 3 || !parseInt(t[0], dim) || !parseInt(t[1], tag))
        fail(lineStart_, "expected 'dim tag \"name\"'");
      if (dim < 0 || dim > 3) fail(lineStart_, "physical dimension " + t[0] + " outside 0..3");
      at_ = lineStart_;  // the name is quoted and may contain blanks: take it from the raw line
      nextLine(line);
      const std::size_t open = line.find('"'), close = line.rfind('"');
      if (open == std::string::npos || close == open) fail(lineStart_, "physical name must be quoted");
      assembly_.physicalName(static_cast<int>(dim), tag, line.substr(open + 1, close - open - 1));
    }
    expectEnd("PhysicalNames");
  }

  void readEntities() {
    std::int64_t counts[4];
    for (auto &c : counts) c = size("the number of entities");
    for (int dim = 0; dim < 4; ++dim) {
      for (std::int64_t i = 0; i < counts[dim]; ++i) {
        const std::size_t start = at_;
        const std::int64_t tag = int32("an entity tag");
        for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) real("entity coordinate");
        const std::int64_t np = size("the number of physical tags");
        need(static_cast<std::uint64_t>(np), 4, "the physical tags of entity " + std::to_string(tag));
        std::vector<std::int64_t> physicals;
        for (std::int64_t p = 0; p < np; ++p) {
          // Gmsh writes negative physical tags for groups with reversed orientation.
          const std::int64_t pt = int32("a physical tag");
          physicals.push_back(pt < 0 ? -pt : pt);
        }
        if (dim > 0) {
          const std::int64_t nb = size("the number of bounding entities");
          need(static_cast<std::uint64_t>(nb), 4, "the bounding entities of entity " + std::to_string(tag));
          at_ += static_cast<std::size_t>(nb) * 4;
        }
        if (!entityPhysicals_.emplace(std::make_pair(std::int64_t(dim), tag), physicals).second) {
          fail(start, "entity " + std::to_string(dim) + "d " + std::to_string(tag) + " defined twice");
        }
      }
    }
    expectEnd("Entities");
  }

  int dimension(std::int64_t dim, std::size_t start) const {
    if (dim < 0 || dim > 3) fail(start, "entity dimension " + std::to_string(dim) + " outside 0..3");
    return static_cast<int>(dim);
  }

  void readNodes4() {
    const std::int64_t blocks = size("the number of node blocks");
    size("the number of nodes");  // not checked, as in ASCII: Gmsh 4.8's own totals can differ
    size("the smallest node tag");
    size("the largest node tag");
    for (std::int64_t b = 0; b < blocks; ++b) {
      const std::size_t start = at_;
      const int dim = dimension(int32("a node block's entity dimension"), start);
      int32("a node block's entity tag");
      const std::int64_t parametric = int32("a node block's parametric flag");
      if (parametric != 0 && parametric != 1)
        fail(start + 8, "parametric flag " + std::to_string(parametric) + " is not 0 or 1");
      const std::int64_t n = size("the number of nodes in a block");
      const std::uint64_t perNode = 8 + 8 * (3 + static_cast<std::uint64_t>(parametric ? dim : 0));
      need(static_cast<std::uint64_t>(n), perNode, "a node block of " + std::to_string(n) + " nodes");
      std::vector<std::int64_t> tags;
      std::vector<std::size_t> places;
      for (std::int64_t i = 0; i < n; ++i) {
        places.push_back(at_);
        tags.push_back(size("a node tag"));
      }
      for (std::int64_t i = 0; i < n; ++i) {
        Eigen::Vector3d x;
        for (int k = 0; k < 3; ++k) x[k] = real("node coordinate");
        for (int k = 0; k < (parametric ? dim : 0); ++k) real("parametric coordinate");
        const auto k = static_cast<std::size_t>(i);
        assembly_.node(tags[k], x, Place::atByte(places[k]));
      }
    }
    expectEnd("Nodes");
  }

  void readElements4() {
    const std::int64_t blocks = size("the number of element blocks"), total = size("the number of elements");
    size("the smallest element tag");
    size("the largest element tag");
    std::int64_t seen = 0;
    const std::vector<std::int64_t> none;
    for (std::int64_t b = 0; b < blocks; ++b) {
      const std::size_t start = at_;
      const int dim = dimension(int32("an element block's entity dimension"), start);
      const std::int64_t entity = int32("an element block's entity tag");
      const std::int64_t type = int32("an element block's type");
      const std::int64_t n = size("the number of elements in a block");
      const auto found = entityPhysicals_.find({dim, entity});
      if (!entityPhysicals_.empty() && found == entityPhysicals_.end()) {
        fail(start, "element block of entity " + std::to_string(dim) + "d " + std::to_string(entity) +
                        ", which $Entities does not define");
      }
      const std::vector<std::int64_t> &physicals = found == entityPhysicals_.end() ? none : found->second;
      const ElementType *known = elementType(type);
      if (!known) {
        fail(start, "element block of Gmsh type " + std::to_string(type) +
                        ", which Glossa does not know (its node count is needed to read past it)");
      }
      const bool read = assembly_.accepts(
          dim, type, !physicals.empty(), [&] { return assembly_.entityName(dim, entity, physicals); },
          Place::atByte(start));
      need(static_cast<std::uint64_t>(n), 8 * (1 + static_cast<std::uint64_t>(known->nodes)),
           "an element block of " + std::to_string(n) + " elements");
      std::vector<std::int64_t> nodes(static_cast<std::size_t>(known->nodes));
      for (std::int64_t i = 0; i < n; ++i) {
        const Place place = Place::atByte(at_);
        const std::int64_t tag = size("an element tag");
        for (auto &node : nodes) node = size("a node tag");
        assembly_.elementTag(tag, place);
        ++seen;
        if (read) assembly_.element(dim, type, tag, entity, nodes, physicals, place);
      }
    }
    if (seen != total) {
      fail(at_, "$Elements header announces " + std::to_string(total) + " elements, the blocks hold " +
                    std::to_string(seen));
    }
    expectEnd("Elements");
  }

  std::int64_t countLine(const std::string &what) {
    const auto t = tokens(what);
    std::int64_t n = 0;
    if (t.size() != 1 || !parseInt(t[0], n) || n < 0) fail(lineStart_, "expected " + what);
    return n;
  }

  void readNodes2() {
    const std::int64_t n = countLine("the number of nodes");
    need(static_cast<std::uint64_t>(n), 4 + 3 * 8, std::to_string(n) + " nodes");
    for (std::int64_t i = 0; i < n; ++i) {
      const Place place = Place::atByte(at_);
      const std::int64_t tag = int32("a node tag");
      Eigen::Vector3d x;
      for (int k = 0; k < 3; ++k) x[k] = real("node coordinate");
      assembly_.node(tag, x, place);
    }
    expectEnd("Nodes");
  }

  void readElements2() {
    const std::int64_t total = countLine("the number of elements");
    std::int64_t seen = 0;
    while (seen < total) {
      const std::size_t start = at_;
      const std::int64_t type = int32("an element block's type");
      const std::int64_t n = int32("the number of elements in a block");
      const std::int64_t ntags = int32("the number of tags");
      if (n < 0 || n > total - seen) {
        fail(start + 4, "element block of " + std::to_string(n) + " elements where " +
                            std::to_string(total - seen) + " remain of the $Elements count");
      }
      if (ntags < 0 || ntags > 1000) fail(start + 8, "bad number of tags " + std::to_string(ntags));
      const ElementType *known = elementType(type);
      if (!known) {
        fail(start, "element block of Gmsh type " + std::to_string(type) +
                        ", which Glossa does not know (its node count is needed to read past it)");
      }
      need(static_cast<std::uint64_t>(n), 4 * (1 + static_cast<std::uint64_t>(ntags + known->nodes)),
           "an element block of " + std::to_string(n) + " elements");
      std::vector<std::int64_t> tags(static_cast<std::size_t>(ntags)),
          nodes(static_cast<std::size_t>(known->nodes));
      for (std::int64_t i = 0; i < n; ++i) {
        const Place place = Place::atByte(at_);
        const std::int64_t tag = int32("an element tag");
        for (auto &t : tags) t = int32("an element's tag");
        for (auto &node : nodes) node = int32("a node tag");
        assembly_.elementTag(tag, place);
        ++seen;
        // The first tag is the physical group (0: none), the second the elementary entity.
        const std::int64_t physical = ntags >= 1 ? tags[0] : 0, entity = ntags >= 2 ? tags[1] : 0;
        const std::vector<std::int64_t> physicals =
            physical == 0 ? std::vector<std::int64_t>{} : std::vector<std::int64_t>{physical};
        if (assembly_.accepts(
                known->dim, type, physical != 0,
                [&] { return assembly_.entityName(known->dim, entity, physicals); }, place)) {
          assembly_.element(known->dim, type, tag, entity, nodes, physicals, place);
        }
      }
    }
    expectEnd("Elements");
  }

  Assembly assembly_;
  std::string data_;
  std::size_t at_ = 0;         // the next byte to read
  std::size_t lineStart_ = 0;  // where the last line read began
  bool msh2_ = false;
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::int64_t>> entityPhysicals_;  // 4.1
};

}  // namespace

ImportedMesh parseBinary(const std::string &file) { return BinaryParser(file).parse(); }

}  // namespace glossa::mesh::gmsh
