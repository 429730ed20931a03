#include "contact/StlReader.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <map>

#include "contact/SurfaceError.hpp"
#include "contact/SurfaceText.hpp"

namespace glossa::contact {

namespace {

using surface_text::fail;

// Merges corners with bitwise-equal coordinates into one vertex, in the order first met.
class VertexWelder {
 public:
  int index(const Eigen::Vector3d &x) {
    const auto [it, fresh] =
        ids_.emplace(std::array<double, 3>{x.x(), x.y(), x.z()}, static_cast<int>(vertices.size()));
    if (fresh) vertices.push_back(x);
    return it->second;
  }
  std::vector<Eigen::Vector3d> vertices;

 private:
  std::map<std::array<double, 3>, int> ids_;
};

std::uint32_t littleEndian32(const std::string &bytes, std::size_t offset) {
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(bytes[offset + k]);
  return v;
}

float littleEndianFloat(const std::string &bytes, std::size_t offset) {
  const std::uint32_t bits = littleEndian32(bytes, offset);
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

TriangleSurface readBinary(const std::string &path, const std::string &bytes, double scale) {
  const std::uint32_t n = littleEndian32(bytes, 80);
  VertexWelder welder;
  std::vector<TriangleSurface::Triangle> triangles(n);
  SurfaceSource source{path, true, std::vector<std::size_t>(n)};
  for (std::uint32_t t = 0; t < n; ++t) {
    const std::size_t record = 84 + 50 * static_cast<std::size_t>(t);
    source.locations[t] = record;
    for (int c = 0; c < 3; ++c) {
      Eigen::Vector3d x;
      for (int d = 0; d < 3; ++d) {
        const std::size_t at = record + 12 + 12 * c + 4 * d;
        x[d] = littleEndianFloat(bytes, at);
        if (!std::isfinite(x[d])) {
          throw SurfaceError(path + ": byte " + std::to_string(at) + ": triangle " + std::to_string(t + 1) +
                             " has a coordinate that is not a finite number");
        }
      }
      triangles[t][c] = welder.index(scale * x);
    }
  }
  if (n == 0) throw SurfaceError(path + ": a binary STL with no triangles");
  return TriangleSurface(std::move(welder.vertices), std::move(triangles), std::move(source));
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// solid [name] { facet normal a b c / outer loop / vertex x y z (3x) / endloop / endfacet } endsolid [name]
TriangleSurface readAscii(const std::string &path, const std::string &text, double scale) {
  enum class Expect { Solid, FacetOrEnd, OuterLoop, Vertex, EndLoop, EndFacet };
  Expect expect = Expect::Solid;
  VertexWelder welder;
  std::vector<TriangleSurface::Triangle> triangles;
  SurfaceSource source{path, false, {}};
  int corner = 0;
  surface_text::Lines lines(text);
  for (std::string line; lines.next(line);) {
    const std::vector<std::string> tok = surface_text::tokens(line);
    if (tok.empty()) continue;
    const std::string word = lower(tok[0]);
    const auto unexpected = [&](const char *wanted) {
      fail(path, lines.number(), "expected " + std::string(wanted) + ", found '" + tok[0] + "'");
    };
    switch (expect) {
      case Expect::Solid:
        if (word != "solid") unexpected("'solid'");
        expect = Expect::FacetOrEnd;
        break;
      case Expect::FacetOrEnd:
        if (word == "endsolid") {
          expect = Expect::Solid;
        } else if (word == "facet") {
          double ignored = 0;  // the stored normal: its numbers must be numbers, its value is not used
          if (tok.size() != 5 || lower(tok[1]) != "normal" || !surface_text::parseDouble(tok[2], ignored) ||
              !surface_text::parseDouble(tok[3], ignored) || !surface_text::parseDouble(tok[4], ignored)) {
            unexpected("'facet normal nx ny nz'");
          }
          triangles.emplace_back();
          source.locations.push_back(lines.number());
          expect = Expect::OuterLoop;
        } else {
          unexpected("'facet' or 'endsolid'");
        }
        break;
      case Expect::OuterLoop:
        if (word != "outer" || tok.size() != 2 || lower(tok[1]) != "loop") unexpected("'outer loop'");
        corner = 0;
        expect = Expect::Vertex;
        break;
      case Expect::Vertex: {
        if (word != "vertex") unexpected("'vertex' (a facet has 3)");
        if (tok.size() != 4)
          fail(path, lines.number(), "a vertex has 3 coordinates, found " + std::to_string(tok.size() - 1));
        Eigen::Vector3d x;
        for (int d = 0; d < 3; ++d) {
          if (!surface_text::parseDouble(tok[d + 1], x[d]))
            fail(path, lines.number(), "bad coordinate '" + tok[d + 1] + "'");
        }
        triangles.back()[corner] = welder.index(scale * x);
        if (++corner == 3) expect = Expect::EndLoop;
        break;
      }
      case Expect::EndLoop:
        if (word != "endloop")
          unexpected(word == "vertex" ? "'endloop' (a facet has 3 vertices, not more)" : "'endloop'");
        expect = Expect::EndFacet;
        break;
      case Expect::EndFacet:
        if (word != "endfacet") unexpected("'endfacet'");
        expect = Expect::FacetOrEnd;
        break;
    }
  }
  if (expect != Expect::Solid) fail(path, lines.number() + 1, "the file ends inside a solid (no 'endsolid')");
  if (triangles.empty()) throw SurfaceError(path + ": an ASCII STL with no facets");
  return TriangleSurface(std::move(welder.vertices), std::move(triangles), std::move(source));
}

}  // namespace

TriangleSurface readStl(const std::string &path, double scale) {
  surface_text::checkScale(scale);
  const std::string bytes = surface_text::readBytes(path);
  const bool sized =
      bytes.size() >= 84 && bytes.size() == 84 + 50 * static_cast<std::uint64_t>(littleEndian32(bytes, 80));
  if (sized) return readBinary(path, bytes, scale);
  const std::size_t first = bytes.find_first_not_of(" \t\r\n");
  const bool solid = first != std::string::npos && lower(bytes.substr(first, 5)) == "solid";
  if (!solid || bytes.find('\0') != std::string::npos) {
    const std::string count =
        bytes.size() >= 84 ? std::to_string(littleEndian32(bytes, 80)) + " (bytes 80-83)" : "n";
    throw SurfaceError(
        path + ": neither an ASCII STL (" +
        std::string(solid ? "it starts with 'solid' but holds NUL bytes" : "it does not start with 'solid'") +
        ") nor a binary one (" + std::to_string(bytes.size()) + " bytes, where a binary STL of " + count +
        " triangles has 84 + 50 n bytes)");
  }
  return readAscii(path, bytes, scale);
}

}  // namespace glossa::contact
