#pragma once
// What every mesh reader returns: the mesh in Glossa's 0-based numbering plus the ids the file
// used, because decks, fibre files and users' notes refer to the file's ids.

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "mesh/HexMesh.hpp"

namespace glossa::mesh {

struct ImportedMesh {
  HexMesh mesh;
  std::vector<std::int64_t> nodeFileIds;     // nodeFileIds[n]: the file's id of node n
  std::vector<std::int64_t> elementFileIds;  // elementFileIds[e]: the file's id of element e
  std::string source;                        // the file the mesh was read from (for messages)
  // What the reader changed on the way in and the user should know (e.g. second-order elements
  // made trilinear): not errors; the deck and `glossa mesh` print them.
  std::vector<std::string> notes;

  // Glossa's index of a file id. Throws std::runtime_error naming the id and the source.
  NodeId nodeOfFileId(std::int64_t fileId) const;
  ElementId elementOfFileId(std::int64_t fileId) const;
  bool hasNodeFileId(std::int64_t fileId) const { return nodeIndex_.count(fileId) != 0; }
  bool hasElementFileId(std::int64_t fileId) const { return elementIndex_.count(fileId) != 0; }

  // Rebuilds the id -> index maps from nodeFileIds / elementFileIds (readers call it once).
  void indexFileIds();

 private:
  std::unordered_map<std::int64_t, NodeId> nodeIndex_;
  std::unordered_map<std::int64_t, ElementId> elementIndex_;
};

}  // namespace glossa::mesh
