#include "mesh/MovedNodes.hpp"

#include <set>

#include "mesh/ImportSupport.hpp"

namespace glossa::mesh {

void moveNodes(const std::string &file, ImportedMesh &imported) {
  importing::LineReader in(file);
  std::set<std::int64_t> seen;
  std::string raw;
  while (in.next(raw)) {
    std::string line = raw.substr(0, raw.find_first_of("!#"));
    const auto tokens = importing::splitWhitespace(line);
    if (tokens.empty()) continue;
    if (tokens.size() != 4) in.fail("expected 'id x y z', found " + std::to_string(tokens.size()) + " fields");
    std::int64_t id = 0;
    if (!importing::parseInt(tokens[0], id)) in.fail("'" + tokens[0] + "' is not a node id");
    if (!imported.hasNodeFileId(id)) in.fail("node " + std::to_string(id) + " is not in the mesh (" + imported.source + ")");
    if (!seen.insert(id).second) in.fail("node " + std::to_string(id) + " is moved twice");
    Eigen::Vector3d x;
    for (int k = 0; k < 3; ++k)
      if (!importing::parseDouble(tokens[static_cast<std::size_t>(k) + 1], x[k]))
        in.fail("'" + tokens[static_cast<std::size_t>(k) + 1] + "' is not a coordinate [m]");
    imported.mesh.nodes[imported.nodeOfFileId(id)] = x;
  }
  if (seen.empty()) importing::fail(file, 0, "no moved nodes");
  importing::checkElements(imported.mesh, imported.elementFileIds, [&file](std::size_t, const std::string &reason) {
    importing::fail(file, 0, "with these nodes moved, " + reason);
  });
}

}  // namespace glossa::mesh
