#include "contact/ObjReader.hpp"

#include <limits>
#include <set>

#include "contact/SurfaceError.hpp"
#include "contact/SurfaceText.hpp"
#include "mesh/ImportSupport.hpp"

namespace glossa::contact {

namespace {

using surface_text::fail;

Eigen::Vector3d readVertex(const std::vector<std::string> &tok, const std::string &path, std::size_t line) {
  const std::size_t n = tok.size() - 1;
  if (n != 3 && n != 4 && n != 6) {
    fail(path, line,
         "a vertex 'v' has 3 coordinates (4 with a weight, 6 with a colour), found " + std::to_string(n));
  }
  double c[6];
  for (std::size_t k = 0; k < n; ++k) {
    if (!surface_text::parseDouble(tok[k + 1], c[k]))
      fail(path, line, "bad vertex coordinate '" + tok[k + 1] + "'");
  }
  const double w = n == 4 ? c[3] : 1.0;
  if (w == 0) fail(path, line, "a vertex weight of 0 puts the vertex at infinity");
  return Eigen::Vector3d(c[0], c[1], c[2]) / w;
}

// One corner "v[/vt[/vn]]" -> 0-based vertex index; a positive index may refer to a vertex
// defined further down (checked once the file is read), a negative one counts back from the
// vertices read so far.
int readCorner(const std::string &token, std::size_t verticesSoFar, const std::string &path,
               std::size_t line) {
  std::vector<std::string> parts{""};
  for (char ch : token) {
    if (ch == '/')
      parts.emplace_back();
    else
      parts.back() += ch;
  }
  std::int64_t index = 0, ignored = 0;
  bool ok = parts.size() <= 3 && mesh::importing::parseInt(parts[0], index) && index != 0 &&
            index <= std::numeric_limits<int>::max();
  // The texture and normal indices are ignored but must be well formed.
  for (std::size_t k = 1; ok && k < parts.size(); ++k)
    ok = parts[k].empty() || mesh::importing::parseInt(parts[k], ignored);
  if (!ok)
    fail(path, line,
         "bad face corner '" + token + "': expected v, v/vt, v//vn or v/vt/vn with a non-zero index v");
  if (index < 0) {
    const std::int64_t resolved = static_cast<std::int64_t>(verticesSoFar) + index;
    if (resolved < 0) {
      fail(path, line,
           "face corner '" + token + "' counts back past the first vertex (" + std::to_string(verticesSoFar) +
               " read so far)");
    }
    return static_cast<int>(resolved);
  }
  return static_cast<int>(index - 1);
}

}  // namespace

TriangleSurface readObj(const std::string &path, double scale) {
  surface_text::checkScale(scale);
  const std::string text = surface_text::readBytes(path);
  static const std::set<std::string> kIgnored = {"vt", "vn", "vp", "g", "o", "s", "usemtl", "mtllib"};
  std::vector<Eigen::Vector3d> vertices;
  std::vector<TriangleSurface::Triangle> triangles;
  SurfaceSource source{path, false, {}};
  surface_text::Lines lines(text);
  for (std::string line; lines.next(line);) {
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    const std::vector<std::string> tok = surface_text::tokens(line);
    if (tok.empty() || kIgnored.count(tok[0])) continue;
    if (tok[0] == "v") {
      vertices.push_back(scale * readVertex(tok, path, lines.number()));
    } else if (tok[0] == "f") {
      if (tok.size() < 4)
        fail(path, lines.number(), "a face has at least 3 corners, found " + std::to_string(tok.size() - 1));
      std::vector<int> corners;
      for (std::size_t k = 1; k < tok.size(); ++k)
        corners.push_back(readCorner(tok[k], vertices.size(), path, lines.number()));
      for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
        triangles.push_back({corners[0], corners[k], corners[k + 1]});
        source.locations.push_back(lines.number());
      }
    } else {
      fail(path, lines.number(),
           "unsupported statement '" + tok[0] +
               "': a surface is read from v and f (vt, vn, vp, g, o, s, usemtl, mtllib are read past)");
    }
  }
  if (triangles.empty()) throw SurfaceError(path + ": no faces ('f' lines)");
  return TriangleSurface(std::move(vertices), std::move(triangles), std::move(source));
}

}  // namespace glossa::contact
