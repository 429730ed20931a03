#include "mesh/MeshWriter.hpp"

#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "mesh/MeshError.hpp"

namespace glossa::mesh {

namespace {

// Round-trip precision: the readers get back the very doubles.
std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

void save(const std::string &file, const std::string &text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  out.close();
  // Not a MeshError: the mesh is fine, the output is not (glossa mesh reports it as such).
  if (!out) throw std::runtime_error(file + ": cannot write");
}

// For each item, the tags (firstTag + index of the set in name order) of the sets holding it.
template <typename Item>
std::map<Item, std::vector<int>> memberships(const std::map<std::string, std::vector<Item>> &sets,
                                             int firstTag) {
  std::map<Item, std::vector<int>> result;
  int tag = firstTag;
  for (const auto &[name, items] : sets) {
    for (const Item &item : items) result[item].push_back(tag);
    ++tag;
  }
  return result;
}

std::string tagList(const std::vector<int> &tags) {
  std::string s = std::to_string(tags.size());
  for (int t : tags) s += " " + std::to_string(t);
  return s;
}

}  // namespace

namespace {

// What the MSH 4.1 sections share: the physical tags (element sets from 1, then face sets, then
// point groups), one volume entity per combination of element sets (elements in none: the empty
// one), one surface per combination of face sets, one point entity per node of a point group.
struct GmshLayout {
  std::map<std::string, std::vector<NodeId>> pointSets;  // node sets that are not face sets' nodes
  int faceTag0 = 0, pointTag0 = 0;
  std::vector<int> volumeOfElement;                        // volume entity (1-based) per element
  std::vector<std::vector<int>> volumes;                   // physical tags per volume entity
  std::map<std::vector<int>, std::vector<ElementFace>> surfaces;  // by physical tags
  std::map<NodeId, std::vector<int>> pointTags;
};

GmshLayout gmshLayout(const HexMesh &mesh, const std::string &file) {
  GmshLayout l;
  // Node sets the surface groups imply are not written again.
  for (const auto &[name, nodes] : mesh.nodeSets) {
    if (!mesh.faceSets.count(name)) {
      l.pointSets[name] = nodes;
    } else if (mesh.nodesOfFaceSet(name) != nodes) {
      throw MeshError(file + ": node set '" + name +
                      "' has the name of a face set but other nodes; in MSH a physical surface's "
                      "group gives its nodes under its name, so the two cannot be told apart: rename one, "
                      "or write .inp");
    }
  }
  auto checkName = [&](const std::string &name) {
    if (name.find('"') != std::string::npos) throw MeshError(file + ": set name '" + name + "' holds a '\"'");
  };
  for (const auto &[name, s] : mesh.elementSets) checkName(name);
  for (const auto &[name, s] : mesh.faceSets) checkName(name);
  for (const auto &[name, s] : l.pointSets) checkName(name);
  l.faceTag0 = 1 + static_cast<int>(mesh.elementSets.size());
  l.pointTag0 = l.faceTag0 + static_cast<int>(mesh.faceSets.size());

  const auto elementTags = memberships(mesh.elementSets, 1);
  std::map<std::vector<int>, int> volumeOf;
  l.volumeOfElement.resize(mesh.numElements());
  for (std::size_t e = 0; e < mesh.numElements(); ++e) {
    const auto it = elementTags.find(static_cast<ElementId>(e));
    const std::vector<int> tags = it == elementTags.end() ? std::vector<int>{} : it->second;
    l.volumeOfElement[e] = volumeOf.emplace(tags, static_cast<int>(volumeOf.size()) + 1).first->second;
  }
  l.volumes.resize(volumeOf.size());
  for (const auto &[tags, v] : volumeOf) l.volumes[static_cast<std::size_t>(v - 1)] = tags;
  for (const auto &[face, tags] : memberships(mesh.faceSets, l.faceTag0)) l.surfaces[tags].push_back(face);
  l.pointTags = memberships(l.pointSets, l.pointTag0);
  return l;
}

void writePhysicalNames(const HexMesh &mesh, const GmshLayout &l, std::ostream &out) {
  out << "$PhysicalNames\n" << mesh.elementSets.size() + mesh.faceSets.size() + l.pointSets.size() << "\n";
  int tag = 1;
  for (const auto &[name, s] : mesh.elementSets) out << "3 " << tag++ << " \"" << name << "\"\n";
  for (const auto &[name, s] : mesh.faceSets) out << "2 " << tag++ << " \"" << name << "\"\n";
  for (const auto &[name, s] : l.pointSets) out << "0 " << tag++ << " \"" << name << "\"\n";
  out << "$EndPhysicalNames\n";
}

void writeEntities(const HexMesh &mesh, const GmshLayout &l, std::ostream &out) {
  const auto [lo, hi] = boundingBox(mesh);
  std::string box;
  for (int i = 0; i < 3; ++i) box += number(lo[i]) + " ";
  for (int i = 0; i < 3; ++i) box += number(hi[i]) + " ";
  out << "$Entities\n" << l.pointTags.size() << " 0 " << l.surfaces.size() << " " << l.volumes.size() << "\n";
  for (const auto &[node, tags] : l.pointTags) {
    const auto &x = mesh.nodes[static_cast<std::size_t>(node)];
    out << node + 1 << " " << number(x.x()) << " " << number(x.y()) << " " << number(x.z()) << " "
        << tagList(tags) << "\n";
  }
  int entity = 1;
  for (const auto &[tags, faces] : l.surfaces) out << entity++ << " " << box << tagList(tags) << " 0\n";
  for (std::size_t v = 0; v < l.volumes.size(); ++v) out << v + 1 << " " << box << tagList(l.volumes[v]) << " 0\n";
  out << "$EndEntities\n";
}

// Nodes in the mesh's order: runs of nodes in volume entity 1, each point-group node in a block
// of its point entity.
void writeNodes(const HexMesh &mesh, const GmshLayout &l, std::ostream &out) {
  auto isPoint = [&](std::size_t n) { return l.pointTags.count(static_cast<NodeId>(n)) != 0; };
  std::vector<std::pair<std::size_t, std::size_t>> runs;  // [begin, end) of nodes in one block
  for (std::size_t n = 0; n < mesh.numNodes(); ++n) {
    if (isPoint(n) || runs.empty() || isPoint(runs.back().second - 1)) {
      runs.push_back({n, n + 1});
    } else {
      runs.back().second = n + 1;
    }
  }
  out << "$Nodes\n" << runs.size() << " " << mesh.numNodes() << " 1 " << mesh.numNodes() << "\n";
  for (const auto &[begin, end] : runs) {
    out << (isPoint(begin) ? "0 " + std::to_string(begin + 1) : std::string("3 1")) << " 0 " << end - begin << "\n";
    for (std::size_t n = begin; n < end; ++n) out << n + 1 << "\n";
    for (std::size_t n = begin; n < end; ++n) {
      const auto &x = mesh.nodes[n];
      out << number(x.x()) << " " << number(x.y()) << " " << number(x.z()) << "\n";
    }
  }
  out << "$EndNodes\n";
}

// Elements: hexahedra 1..E in blocks of consecutive elements of one entity, then the faces, then
// the points.
void writeElements(const HexMesh &mesh, const GmshLayout &l, std::ostream &out) {
  std::vector<std::pair<std::size_t, std::size_t>> blocks;
  for (std::size_t e = 0; e < mesh.numElements(); ++e) {
    if (blocks.empty() || l.volumeOfElement[blocks.back().second - 1] != l.volumeOfElement[e]) {
      blocks.push_back({e, e + 1});
    } else {
      blocks.back().second = e + 1;
    }
  }
  std::size_t numFaces = 0;
  for (const auto &[tags, faces] : l.surfaces) numFaces += faces.size();
  const std::size_t total = mesh.numElements() + numFaces + l.pointTags.size();
  out << "$Elements\n"
      << blocks.size() + l.surfaces.size() + l.pointTags.size() << " " << total << " 1 " << total << "\n";
  for (const auto &[begin, end] : blocks) {
    out << "3 " << l.volumeOfElement[begin] << " 5 " << end - begin << "\n";
    for (std::size_t e = begin; e < end; ++e) {
      out << e + 1;
      for (NodeId n : mesh.elements[e]) out << " " << n + 1;
      out << "\n";
    }
  }
  std::size_t next = mesh.numElements() + 1;
  int entity = 1;
  for (const auto &[tags, faces] : l.surfaces) {
    out << "2 " << entity++ << " 3 " << faces.size() << "\n";
    for (const ElementFace &f : faces) {
      out << next++;
      for (int a : kHexFaceNodes[static_cast<std::size_t>(f.localFace)])
        out << " " << mesh.elements[static_cast<std::size_t>(f.element)][static_cast<std::size_t>(a)] + 1;
      out << "\n";
    }
  }
  for (const auto &[node, tags] : l.pointTags) out << "0 " << node + 1 << " 15 1\n" << next++ << " " << node + 1 << "\n";
  out << "$EndElements\n";
}

}  // namespace

void writeGmsh(const HexMesh &mesh, const std::string &file) {
  const GmshLayout layout = gmshLayout(mesh, file);
  std::ostringstream out;
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  writePhysicalNames(mesh, layout, out);
  writeEntities(mesh, layout, out);
  writeNodes(mesh, layout, out);
  writeElements(mesh, layout, out);
  save(file, out.str());
}

void writeAbaqus(const HexMesh &mesh, const std::string &file) {
  auto checkName = [&](const std::string &name) {
    if (name.find_first_of(",=") != std::string::npos || name.empty()) {
      throw MeshError(file + ": set name '" + name + "' cannot stand in an Abaqus keyword line (',' or '=')");
    }
  };
  for (const auto &[name, s] : mesh.elementSets) checkName(name);
  for (const auto &[name, s] : mesh.faceSets) checkName(name);
  for (const auto &[name, s] : mesh.nodeSets) checkName(name);

  std::ostringstream out;
  out << "*HEADING\nwritten by glossa mesh\n*NODE\n";
  for (std::size_t n = 0; n < mesh.numNodes(); ++n) {
    const auto &x = mesh.nodes[n];
    out << n + 1 << ", " << number(x.x()) << ", " << number(x.y()) << ", " << number(x.z()) << "\n";
  }
  out << "*ELEMENT, TYPE=C3D8\n";
  for (std::size_t e = 0; e < mesh.numElements(); ++e) {
    out << e + 1;
    for (NodeId n : mesh.elements[e]) out << ", " << n + 1;
    out << "\n";
  }
  // Sixteen ids a line, Abaqus's limit.
  auto ids = [&out](const auto &items) {
    for (std::size_t i = 0; i < items.size(); ++i)
      out << items[i] + 1 << (i % 16 == 15 || i + 1 == items.size() ? "\n" : ", ");
  };
  for (const auto &[name, s] : mesh.elementSets) {
    out << "*ELSET, ELSET=" << name << "\n";
    ids(s);
  }
  for (const auto &[name, s] : mesh.nodeSets) {
    out << "*NSET, NSET=" << name << "\n";
    ids(s);
  }
  for (const auto &[name, faces] : mesh.faceSets) {
    out << "*SURFACE, TYPE=ELEMENT, NAME=" << name << "\n";
    for (const ElementFace &f : faces) out << f.element + 1 << ", S" << f.localFace + 1 << "\n";
  }
  save(file, out.str());
}

}  // namespace glossa::mesh
