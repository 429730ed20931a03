#include "mesh/AnsysReader.hpp"

#include <cctype>
#include <set>
#include <stdexcept>

#include "mesh/ImportSupport.hpp"

namespace glossa::mesh {

using importing::LineReader;
using importing::parseDouble;
using importing::parseInt;
using importing::splitCommas;
using importing::splitWhitespace;
using importing::trim;
using importing::upper;

namespace {

// APDL comments start with '!' anywhere on the line.
std::string stripComment(const std::string &line, const char *markers = "!") {
  const std::size_t pos = line.find_first_of(markers);
  return trim(pos == std::string::npos ? line : line.substr(0, pos));
}

std::int64_t intField(const LineReader &in, const std::string &token, const char *what) {
  std::int64_t v = 0;
  if (!parseInt(token, v)) in.fail(std::string("bad ") + what + " '" + token + "'");
  return v;
}

// "NAME(i,j,k) = value" -> NAME, {i, j, k}, value; false if the line has another shape.
bool parseIndexedAssignment(const std::string &line, std::string &name, std::vector<std::string> &indices,
                            std::string &value) {
  const std::size_t open = line.find('(');
  const std::size_t close = line.find(')');
  const std::size_t eq = line.find('=');
  if (open == std::string::npos || close == std::string::npos || eq == std::string::npos ||
      !(open < close && close < eq)) {
    return false;
  }
  name = upper(trim(line.substr(0, open)));
  indices = splitCommas(line.substr(open + 1, close - open - 1));
  if (!trim(line.substr(close + 1, eq - close - 1)).empty()) return false;
  value = trim(line.substr(eq + 1));
  return true;
}

bool isScalarAssignment(const std::string &line) {
  const std::size_t eq = line.find('=');
  if (eq == std::string::npos || line.find(',') != std::string::npos) return false;
  const std::string lhs = trim(line.substr(0, eq));
  if (lhs.empty()) return false;
  for (char c : lhs) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  }
  return true;
}

}  // namespace

ImportedMesh readAnsysMesh(const std::string &nodeFile, const std::string &elementFile) {
  ImportedMesh result;
  result.source = elementFile;
  std::string line;

  LineReader nodes(nodeFile);
  std::set<std::int64_t> nodeIds;
  while (nodes.next(line)) {
    const auto tokens = splitWhitespace(stripComment(line));
    if (tokens.empty()) continue;
    if (tokens.size() != 4) {
      nodes.fail("expected 'id x y z', found " + std::to_string(tokens.size()) + " fields");
    }
    const std::int64_t id = intField(nodes, tokens[0], "node id");
    Eigen::Vector3d x;
    for (int i = 0; i < 3; ++i) {
      if (!parseDouble(tokens[1 + i], x[i])) nodes.fail("bad coordinate '" + tokens[1 + i] + "'");
    }
    if (!nodeIds.insert(id).second) nodes.fail("duplicate node id " + std::to_string(id));
    result.nodeFileIds.push_back(id);
    result.mesh.nodes.push_back(x);
  }
  if (result.mesh.nodes.empty()) importing::fail(nodeFile, 0, "no nodes");
  result.indexFileIds();

  LineReader elements(elementFile);
  std::set<std::int64_t> elementIds;
  std::vector<std::size_t> lines;
  while (elements.next(line)) {
    const auto tokens = splitWhitespace(stripComment(line));
    if (tokens.empty()) continue;
    if (tokens.size() != 14) {
      elements.fail(
          "expected 8 node ids, MAT TYPE REAL SECNUM ESYS and the element id (14 integers), found " +
          std::to_string(tokens.size()) + " fields");
    }
    std::array<std::int64_t, 14> v;
    for (int i = 0; i < 14; ++i) v[i] = intField(elements, tokens[i], i < 8 ? "node id" : "integer");
    const std::int64_t id = v[13];
    if (!elementIds.insert(id).second) elements.fail("duplicate element id " + std::to_string(id));
    Hex hex;
    for (int a = 0; a < 8; ++a) {
      if (!result.hasNodeFileId(v[a])) {
        elements.fail("element " + std::to_string(id) + " refers to node " + std::to_string(v[a]) +
                      ", which " + nodeFile + " does not define");
      }
      // ANSYS I J K L M N O P = VTK 0..7 (see the header); no permutation.
      hex[a] = result.nodeOfFileId(v[a]);
    }
    result.mesh.elements.push_back(hex);
    result.elementFileIds.push_back(id);
    lines.push_back(elements.lineNumber());
  }
  if (result.mesh.elements.empty()) importing::fail(elementFile, 0, "no elements");
  result.indexFileIds();
  importing::checkElements(result.mesh, elementFile, lines, result.elementFileIds);
  return result;
}

AnsysComponents readAnsysComponents(const std::string &macroFile, ImportedMesh &imported) {
  AnsysComponents result;
  LineReader in(macroFile);
  std::set<ElementId> selection;
  std::size_t cmCount = 0;
  std::map<std::size_t, std::string> declared;
  std::set<std::string> componentNames;
  std::string raw;
  while (in.next(raw)) {
    const std::string line = stripComment(raw);
    if (line.empty()) continue;
    std::string name, value;
    std::vector<std::string> indices;
    if (parseIndexedAssignment(line, name, indices, value)) {
      if (name != "MUSCLENAME") continue;  // other arrays do not define sets
      std::int64_t i = 0;
      if (indices.size() != 1 || !parseInt(indices[0], i) || i < 1) in.fail("bad index in muscleName(...)");
      if (value.size() < 2 || value.front() != '\'' || value.back() != '\'') {
        in.fail("muscleName value must be a quoted string, found " + value);
      }
      declared[static_cast<std::size_t>(i)] = trim(value.substr(1, value.size() - 2));
      continue;
    }
    if (line[0] == '*' || line[0] == '/' || isScalarAssignment(line)) continue;

    const auto f = splitCommas(line);
    const std::string command = upper(f[0]);
    if (command == "ESEL") {
      const std::string type = f.size() > 1 ? upper(f[1]) : "";
      if (type == "NONE" || type == "ALL") {
        selection.clear();
        if (type == "ALL") {
          for (std::size_t e = 0; e < imported.mesh.numElements(); ++e)
            selection.insert(static_cast<ElementId>(e));
        }
        continue;
      }
      if (type != "S" && type != "A" && type != "U" && type != "R") {
        in.fail("ESEL type '" + (f.size() > 1 ? f[1] : std::string()) +
                "' not supported (S, A, U, R, ALL, NONE)");
      }
      if (f.size() < 5 || upper(f[2]) != "ELEM") in.fail("expected ESEL," + type + ",ELEM,,min[,max[,inc]]");
      const std::int64_t lo = intField(in, f[4], "element id");
      const std::int64_t hi = f.size() > 5 && !f[5].empty() ? intField(in, f[5], "element id") : lo;
      const std::int64_t inc = f.size() > 6 && !f[6].empty() ? intField(in, f[6], "increment") : 1;
      if (f.size() > 7) in.fail("too many fields for ESEL");
      if (inc < 1) in.fail("ESEL increment must be positive, found " + std::to_string(inc));
      if (hi < lo) in.fail("ESEL range " + std::to_string(lo) + ".." + std::to_string(hi) + " is empty");
      std::set<ElementId> range;
      for (std::int64_t id = lo; id <= hi; id += inc) {
        if (!imported.hasElementFileId(id)) {
          in.fail("element " + std::to_string(id) + " is not in the mesh (" + imported.source + ")");
        }
        range.insert(imported.elementOfFileId(id));
      }
      if (type == "S") {
        selection = range;
      } else if (type == "A") {
        selection.insert(range.begin(), range.end());
      } else if (type == "U") {
        for (ElementId e : range) selection.erase(e);
      } else {  // R: reselect within the current selection
        std::set<ElementId> kept;
        for (ElementId e : range) {
          if (selection.count(e)) kept.insert(e);
        }
        selection = kept;
      }
    } else if (command == "CM") {
      if (f.size() < 3 || f[1].empty() || upper(f[2]) != "ELEM") in.fail("expected CM,name,ELEM");
      const std::string cmName = f[1];
      ++cmCount;
      const auto d = declared.find(cmCount);
      if (d != declared.end() && d->second != cmName) {
        in.fail("component " + std::to_string(cmCount) + " is named '" + cmName + "' but muscleName(" +
                std::to_string(cmCount) + ") = '" + d->second + "'");
      }
      if (!componentNames.insert(cmName).second) in.fail("component '" + cmName + "' defined twice");
      if (selection.empty()) {
        result.emptyComponents.push_back(cmName);
        continue;
      }
      result.names.push_back(cmName);
      imported.mesh.elementSets[cmName] = std::vector<ElementId>(selection.begin(), selection.end());
    } else if (command == "CMGRP") {
      if (f.size() < 3 || f[1].empty()) in.fail("expected CMGRP,name,component[,component...]");
      std::vector<std::string> members;
      for (std::size_t i = 2; i < f.size(); ++i) {
        if (f[i].empty()) continue;
        if (!componentNames.count(f[i]))
          in.fail("CMGRP member '" + f[i] + "' is not a component defined above");
        members.push_back(f[i]);
      }
      result.groups[f[1]] = members;
    } else {
      in.fail("unsupported APDL command '" + f[0] + "' (readable: ESEL, CM, CMGRP, muscleName(i) = '...')");
    }
  }
  for (const auto &[i, n] : declared) result.declaredNames.push_back(n);
  if (declared.size() != (declared.empty() ? 0 : declared.rbegin()->first)) {
    importing::fail(
        macroFile, 0,
        "muscleName(i) is not declared for every i = 1.." + std::to_string(declared.rbegin()->first));
  }
  return result;
}

std::vector<MuscleFibres> readAnsysFibres(const std::string &fibreFile, const ImportedMesh &imported,
                                          const std::vector<std::string> &muscleNames,
                                          const std::map<std::int64_t, Eigen::Vector3d> &externalPoints) {
  const std::size_t nm = muscleNames.size();
  // points[m][f][k], counts as declared, and the line of each declaration for messages.
  std::vector<std::map<std::int64_t, std::map<std::int64_t, FibrePoint>>> points(nm);
  std::vector<std::map<std::int64_t, std::pair<std::int64_t, std::size_t>>> nodesPerFibre(nm);
  std::vector<std::pair<std::int64_t, std::size_t>> fibresPerMuscle(nm, {-1, 0});
  LineReader in(fibreFile);
  std::string raw;
  auto muscleIndex = [&](const std::string &token) {
    const std::int64_t m = intField(in, token, "muscle index");
    if (m < 1 || static_cast<std::size_t>(m) > nm) {
      in.fail("muscle index " + std::to_string(m) + " outside 1.." + std::to_string(nm));
    }
    return static_cast<std::size_t>(m - 1);
  };
  while (in.next(raw)) {
    const std::string line = stripComment(raw);
    if (line.empty()) continue;
    std::string name, value;
    std::vector<std::string> idx;
    if (!parseIndexedAssignment(line, name, idx, value)) {
      if (line[0] == '*' || line[0] == '/' || isScalarAssignment(line)) continue;
      in.fail("expected FIBER(k,f,m)=node, NB_NODES_FIBER(f,m)=n or NB_FIBERS(m)=n");
    }
    if (name == "FIBER") {
      if (idx.size() != 3) in.fail("FIBER needs three indices (k,f,m)");
      const std::int64_t k = intField(in, idx[0], "node index"), f = intField(in, idx[1], "fibre index");
      const std::size_t m = muscleIndex(idx[2]);
      const std::int64_t id = intField(in, value, "node id");
      if (k < 1 || f < 1) in.fail("FIBER indices start at 1");
      FibrePoint p;
      p.fileId = id;
      if (imported.hasNodeFileId(id)) {
        p.node = imported.nodeOfFileId(id);
        p.position = imported.mesh.nodes[static_cast<std::size_t>(p.node)];
      } else if (externalPoints.count(id)) {
        p.node = -1;
        p.position = externalPoints.at(id);
      } else {
        in.fail("node " + std::to_string(id) + " is neither a mesh node nor a supplied external point");
      }
      if (!points[m][f].emplace(k, p).second)
        in.fail("FIBER(" + idx[0] + "," + idx[1] + "," + idx[2] + ") given twice");
    } else if (name == "NB_NODES_FIBER") {
      if (idx.size() != 2) in.fail("NB_NODES_FIBER needs two indices (f,m)");
      const std::int64_t f = intField(in, idx[0], "fibre index");
      nodesPerFibre[muscleIndex(idx[1])][f] = {intField(in, value, "count"), in.lineNumber()};
    } else if (name == "NB_FIBERS") {
      if (idx.size() != 1) in.fail("NB_FIBERS needs one index (m)");
      fibresPerMuscle[muscleIndex(idx[0])] = {intField(in, value, "count"), in.lineNumber()};
    }  // other arrays (FIBERS_LOCATION, ...) carry nothing the mesh needs
  }

  std::vector<MuscleFibres> result(nm);
  for (std::size_t m = 0; m < nm; ++m) {
    result[m].muscle = muscleNames[m];
    const auto [nf, nfLine] = fibresPerMuscle[m];
    const std::string label = "muscle " + std::to_string(m + 1) + " (" + muscleNames[m] + ")";
    if (nf < 0) importing::fail(fibreFile, 0, "NB_FIBERS is not given for " + label);
    if (static_cast<std::int64_t>(points[m].size()) != nf || (nf > 0 && points[m].rbegin()->first != nf)) {
      importing::fail(fibreFile, nfLine,
                      "NB_FIBERS = " + std::to_string(nf) + " for " + label + " but FIBER defines fibres " +
                          (points[m].empty() ? std::string("none")
                                             : "1.." + std::to_string(points[m].rbegin()->first) + " (" +
                                                   std::to_string(points[m].size()) + " of them)"));
    }
    for (const auto &[f, byK] : points[m]) {
      const auto n = nodesPerFibre[m].find(f);
      const std::string fibre = "fibre " + std::to_string(f) + " of " + label;
      if (n == nodesPerFibre[m].end())
        importing::fail(fibreFile, 0, "NB_NODES_FIBER is not given for " + fibre);
      const auto [count, countLine] = n->second;
      if (static_cast<std::int64_t>(byK.size()) != count || byK.rbegin()->first != count) {
        importing::fail(fibreFile, countLine,
                        "NB_NODES_FIBER = " + std::to_string(count) + " for " + fibre +
                            " but FIBER gives nodes 1.." + std::to_string(byK.rbegin()->first) + " (" +
                            std::to_string(byK.size()) + " of them)");
      }
      if (count < 2) importing::fail(fibreFile, countLine, fibre + " has fewer than two nodes");
      std::vector<FibrePoint> polyline;
      for (const auto &[k, p] : byK) polyline.push_back(p);
      result[m].fibres.push_back(std::move(polyline));
    }
  }
  return result;
}

void readAnsysNodeList(const std::string &file, const std::string &setName, ImportedMesh &imported) {
  LineReader in(file);
  std::vector<NodeId> nodes;
  std::string raw;
  while (in.next(raw)) {
    for (const std::string &token : splitWhitespace(stripComment(raw, "!#"))) {
      const std::int64_t id = intField(in, token, "node id");
      if (!imported.hasNodeFileId(id)) {
        in.fail("node " + std::to_string(id) + " is not in the mesh (" + imported.source + ")");
      }
      nodes.push_back(imported.nodeOfFileId(id));
    }
  }
  if (nodes.empty()) importing::fail(file, 0, "no node ids");
  importing::sortUnique(nodes);
  imported.mesh.nodeSets[setName] = nodes;
}

AnsysModel readAnsysModel(const AnsysModelFiles &files) {
  AnsysModel model;
  model.imported = readAnsysMesh(files.nodes, files.elements);
  if (!files.components.empty()) model.components = readAnsysComponents(files.components, model.imported);
  if (!files.fibres.empty()) {
    if (files.components.empty()) {
      importing::fail(files.fibres, 0,
                      "fibre muscles are numbered by the component macro's muscleName array; give it");
    }
    const auto &names =
        model.components.declaredNames.empty() ? model.components.names : model.components.declaredNames;
    model.fibres = readAnsysFibres(files.fibres, model.imported, names, files.externalPoints);
  }
  for (const auto &[name, file] : files.nodeSets) readAnsysNodeList(file, name, model.imported);
  return model;
}

}  // namespace glossa::mesh
