#include "mesh/ImportSupport.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "mesh/ImportedMesh.hpp"
#include "mesh/MeshError.hpp"
#include "mesh/MeshQuality.hpp"

namespace glossa::mesh {

NodeId ImportedMesh::nodeOfFileId(std::int64_t fileId) const {
  const auto it = nodeIndex_.find(fileId);
  if (it == nodeIndex_.end()) {
    throw MeshError(source + ": no node with id " + std::to_string(fileId));
  }
  return it->second;
}

ElementId ImportedMesh::elementOfFileId(std::int64_t fileId) const {
  const auto it = elementIndex_.find(fileId);
  if (it == elementIndex_.end()) {
    throw MeshError(source + ": no element with id " + std::to_string(fileId));
  }
  return it->second;
}

void ImportedMesh::indexFileIds() {
  nodeIndex_.clear();
  elementIndex_.clear();
  for (std::size_t n = 0; n < nodeFileIds.size(); ++n) {
    nodeIndex_[nodeFileIds[n]] = static_cast<NodeId>(n);
  }
  for (std::size_t e = 0; e < elementFileIds.size(); ++e) {
    elementIndex_[elementFileIds[e]] = static_cast<ElementId>(e);
  }
}

namespace importing {

void fail(const std::string &file, std::size_t line, const std::string &reason) {
  if (line == 0) throw MeshError(file + ": " + reason);
  throw MeshError(file + ":" + std::to_string(line) + ": " + reason);
}

LineReader::LineReader(std::string path) : path_(std::move(path)) {
  std::ifstream in(path_, std::ios::binary);
  if (!in) importing::fail(path_, 0, "cannot open");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();  // last line without a newline
    std::string line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();  // CRLF files
    lines_.push_back(std::move(line));
    start = end + 1;
  }
}

bool LineReader::next(std::string &line) {
  if (line_ >= lines_.size()) {
    line_ = lines_.size() + 1;  // errors after the end point one past the last line
    return false;
  }
  line = lines_[line_++];
  return true;
}

void LineReader::unread() {
  if (line_ > 0 && line_ <= lines_.size()) --line_;
}

void LineReader::fail(const std::string &reason) const {
  importing::fail(path_, std::min(line_, lines_.size() + 1), reason);
}

std::string trim(const std::string &s) {
  const auto isSpace = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  std::size_t b = 0, e = s.size();
  while (b < e && isSpace(s[b])) ++b;
  while (e > b && isSpace(s[e - 1])) --e;
  return s.substr(b, e - b);
}

std::string upper(std::string s) {
  for (char &c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::vector<std::string> splitWhitespace(const std::string &s) {
  std::vector<std::string> tokens;
  std::istringstream in(s);
  std::string t;
  while (in >> t) tokens.push_back(t);
  return tokens;
}

std::vector<std::string> splitCommas(const std::string &s) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = s.find(',', start);
    fields.push_back(trim(s.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return fields;
}

bool parseInt(const std::string &token, std::int64_t &value) {
  if (token.empty()) return false;
  errno = 0;
  char *end = nullptr;
  const long long v = std::strtoll(token.c_str(), &end, 10);
  if (errno != 0 || end != token.c_str() + token.size()) return false;
  value = v;
  return true;
}

bool parseDouble(const std::string &token, double &value) {
  if (token.empty()) return false;
  errno = 0;
  char *end = nullptr;
  // Fortran-style exponents (1.0D-3) appear in ANSYS and Abaqus files.
  std::string t = token;
  for (char &c : t) {
    if (c == 'd' || c == 'D') c = 'e';
  }
  const double v = std::strtod(t.c_str(), &end);
  if (errno == ERANGE || end != t.c_str() + t.size() || !std::isfinite(v)) return false;
  value = v;
  return true;
}

void checkElements(const HexMesh &mesh, const std::string &file, const std::vector<std::size_t> &lines,
                   const std::vector<std::int64_t> &fileIds) {
  checkElements(mesh, fileIds, [&](std::size_t e, const std::string &reason) { fail(file, lines[e], reason); });
}

void checkElements(const HexMesh &mesh, const std::vector<std::int64_t> &fileIds,
                   const std::function<void(std::size_t e, const std::string &reason)> &refuse) {
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const Hex &hex = mesh.elements[e];
    for (int a = 0; a < 8; ++a) {
      for (int b = a + 1; b < 8; ++b) {
        if (hex[a] == hex[b]) {
          refuse(e, "element " + std::to_string(fileIds[e]) + " repeats a node (local nodes " +
                        std::to_string(a + 1) + " and " + std::to_string(b + 1) +
                        "): not a hexahedron (collapsed wedges and tetrahedra are not supported)");
        }
      }
    }
    const double detJ = minGaussPointJacobian(mesh.elementCoordinates(static_cast<ElementId>(e)));
    if (!(detJ > 0.0)) {
      std::ostringstream reason;
      reason << "element " << fileIds[e] << " is inverted or degenerate: det(dX/dxi) = " << detJ
             << " at a Gauss point (check the node order)";
      refuse(e, reason.str());
    }
  }
}

FaceLocator::FaceLocator(const HexMesh &mesh) : mesh_(mesh) {
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    for (int f = 0; f < 6; ++f) {
      std::array<NodeId, 4> key;
      for (int a = 0; a < 4; ++a) key[a] = mesh.elements[e][kHexFaceNodes[f][a]];
      std::sort(key.begin(), key.end());
      faces_[key].push_back({static_cast<ElementId>(e), f});
    }
  }
}

bool FaceLocator::find(const std::array<NodeId, 4> &quad, ElementFace &face) const {
  std::array<NodeId, 4> key = quad;
  std::sort(key.begin(), key.end());
  const auto it = faces_.find(key);
  if (it == faces_.end()) return false;
  if (it->second.size() == 1) {
    face = it->second.front();
    return true;
  }
  // Interior face: the element whose outward face order is a rotation of the quad's order.
  for (const ElementFace &candidate : it->second) {
    const Hex &hex = mesh_.elements[static_cast<std::size_t>(candidate.element)];
    std::array<NodeId, 4> nodes;
    for (int a = 0; a < 4; ++a) nodes[a] = hex[kHexFaceNodes[candidate.localFace][a]];
    for (int shift = 0; shift < 4; ++shift) {
      bool same = true;
      for (int a = 0; a < 4; ++a) same = same && nodes[(a + shift) % 4] == quad[a];
      if (same) {
        face = candidate;
        return true;
      }
    }
  }
  face = it->second.front();
  return true;
}

}  // namespace importing
}  // namespace glossa::mesh
