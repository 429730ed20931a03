#pragma once
// Pieces the mesh readers share: a line reader that tolerates CRLF, Latin-1 bytes and a missing
// final newline; "file:line: reason" errors; strict number parsing; the element checks every
// importer must apply (distinct nodes, positive Jacobian at the Gauss points); and matching of
// boundary quadrilaterals to hexahedron faces.

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "mesh/HexMesh.hpp"

namespace glossa::mesh::importing {

// Throws std::runtime_error("file:line: reason"); line 0 means "the file as a whole".
[[noreturn]] void fail(const std::string &file, std::size_t line, const std::string &reason);

// The file's lines without their terminators ("\n", "\r\n" or a lone final line without
// either). Bytes are kept as they are: comments in ISO-8859-1 pass through untouched.
class LineReader {
 public:
  explicit LineReader(std::string path);  // throws "path: cannot open"

  // Next line into `line`; false at the end of the file.
  bool next(std::string &line);
  // Pushes the last line back so that the next call to next() returns it again.
  void unread();
  std::size_t lineNumber() const { return line_; }
  const std::string &path() const { return path_; }
  [[noreturn]] void fail(const std::string &reason) const;

 private:
  std::string path_;
  std::vector<std::string> lines_;
  std::size_t line_ = 0;  // 1-based number of the last line returned
};

std::string trim(const std::string &s);
std::string upper(std::string s);
std::vector<std::string> splitWhitespace(const std::string &s);
// Splits at commas and trims each field; "a, b," gives {"a", "b", ""}.
std::vector<std::string> splitCommas(const std::string &s);

// Whole-token parses: "12x" and "" fail, and so does a non-finite double.
bool parseInt(const std::string &token, std::int64_t &value);
bool parseDouble(const std::string &token, double &value);

// Refuses, naming `file:line` and the element's file id, an element that repeats a node (not a
// hexahedron) or whose det(dX/dxi) is not positive at one of the 2x2x2 Gauss points.
// lines[e] and fileIds[e] locate element e in the file.
void checkElements(const HexMesh &mesh, const std::string &file, const std::vector<std::size_t> &lines,
                   const std::vector<std::int64_t> &fileIds);
// The same checks for readers that locate elements otherwise (a byte offset in a binary file):
// `refuse(e, reason)` must throw.
void checkElements(const HexMesh &mesh, const std::vector<std::int64_t> &fileIds,
                   const std::function<void(std::size_t e, const std::string &reason)> &refuse);

// Finds hexahedron faces by their four nodes (any order, any rotation).
class FaceLocator {
 public:
  explicit FaceLocator(const HexMesh &mesh);
  // The element face with these nodes. If two elements share the face (an interior surface),
  // the one for which the quadrilateral's right-hand normal points outwards is chosen; a
  // boundary face is returned whatever the quadrilateral's orientation. Returns false if no
  // element has such a face.
  bool find(const std::array<NodeId, 4> &quad, ElementFace &face) const;

 private:
  const HexMesh &mesh_;
  std::map<std::array<NodeId, 4>, std::vector<ElementFace>> faces_;
};

// Sorts and removes duplicates (sets in HexMesh are sorted and unique).
template <typename T>
void sortUnique(std::vector<T> &v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace glossa::mesh::importing
