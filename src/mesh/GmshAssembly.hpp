#pragma once
// What every MSH parser (2.2 and 4.1, ASCII and binary) hands its findings to: the physical
// names, the nodes and the elements with their physical groups. The rules that turn them into a
// HexMesh live here once, so that the four encodings cannot drift apart: which Gmsh element types
// are read and how, which are refused and with what advice, how physical groups become sets,
// and which nodes a second-order mesh leaves behind.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "mesh/ImportedMesh.hpp"

namespace glossa::mesh::gmsh {

// A place in the file for messages: a line of an ASCII section or a byte offset in a binary one.
struct Place {
  std::size_t line = 0;
  std::size_t byte = 0;
  bool binary = false;
  static Place atLine(std::size_t line) { return {line, 0, false}; }
  static Place atByte(std::size_t byte) { return {0, byte, true}; }
};

// Throws MeshError "file:line: reason" or, in binary data, "file: byte N: reason".
[[noreturn]] void fail(const std::string &file, Place place, const std::string &reason);

// A Gmsh element type: its dimension, its node count (needed to step over elements in binary
// data) and how many of its nodes are corners (Gmsh lists the corners first, in the order of
// the first-order element, then the edge, face and interior nodes).
struct ElementType {
  int dim;
  int nodes;
  int corners;
  const char *name;
};
// nullptr for a type Glossa does not know.
const ElementType *elementType(std::int64_t type);
// "type 5 (8-node hexahedron)".
std::string typeName(std::int64_t type);

class Assembly {
 public:
  explicit Assembly(std::string file);

  const std::string &file() const { return file_; }
  [[noreturn]] void fail(Place place, const std::string &reason) const { gmsh::fail(file_, place, reason); }

  void physicalName(int dim, std::int64_t tag, std::string name);
  void node(std::int64_t tag, const Eigen::Vector3d &x, Place place);
  // Refuses a duplicate element tag (in every block, read or skipped).
  void elementTag(std::int64_t tag, Place place);

  // Whether elements of `type` in an entity of dimension `dim` are read: hexahedra (first or
  // second order) in volumes always, quadrangles, lines and points only in physical groups
  // (`grouped`); other elements of ungrouped lower-dimensional entities are skipped. Anything
  // else is refused naming the type, with advice for tetrahedra, prisms, pyramids and
  // triangles (triangles only at finish(), so that tetrahedra met later are named first).
  // `where` names the entity for the message ("volume entity 2"), built only when needed.
  bool accepts(int dim, std::int64_t type, bool grouped, const std::function<std::string()> &where,
               Place place);

  // An accepted element: `nodes` holds the type's node tags in Gmsh order; `physicals` the
  // physical tags of its entity. `entity` keys the MSH 2 duplicates (see GmshAssembly.cpp).
  void element(int dim, std::int64_t type, std::int64_t tag, std::int64_t entity,
               const std::vector<std::int64_t> &nodes, const std::vector<std::int64_t> &physicals,
               Place place);

  // "volume entity 2" or, in groups, "surface entity 1 (physical 'floor')", for messages.
  std::string entityName(int dim, std::int64_t tag, const std::vector<std::int64_t> &physicals) const;

  // The mesh, checked, with its sets; `end` locates whole-file errors.
  ImportedMesh finish(Place end);

 private:
  NodeId nodeOf(std::int64_t tag, std::int64_t element, Place place) const;
  std::string groupName(std::int64_t dim, std::int64_t tag) const;
  void dropMidsideNodes();

  struct Quad {
    std::array<NodeId, 4> nodes;
    Place place;
    std::int64_t tag;
  };

  std::string file_;
  ImportedMesh result_;
  std::unordered_map<std::int64_t, NodeId> nodeIndex_;
  std::set<std::int64_t> elementTags_;
  std::map<std::pair<std::int64_t, std::int64_t>, std::string> physicalNames_;  // (dim, tag)
  std::vector<Place> elementPlaces_;
  std::vector<std::vector<std::int64_t>> elementPhysicals_;  // per element: its physical tags
  // MSH 2 writes an element once per physical group of its entity: (entity, nodes) -> element.
  std::map<std::pair<std::int64_t, Hex>, ElementId> hexByEntityAndNodes_;
  std::map<std::int64_t, std::vector<ElementId>> volumeMembers_;
  std::map<std::int64_t, std::vector<Quad>> surfaceMembers_;
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<NodeId>> lowerMembers_;  // (dim, tag)
  std::vector<bool> cornerNode_, midsideNode_;  // per node: a corner / a higher-order node of some element
  std::optional<std::pair<Place, std::string>> pendingRefusal_;  // triangles in a face set
  std::map<std::int64_t, std::size_t> secondOrderCount_;  // Gmsh type -> elements read by their corners
};

}  // namespace glossa::mesh::gmsh
