#include "contact/TriangleSurface.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>

#include "contact/SurfaceError.hpp"

namespace glossa::contact {

namespace {

// A triangle whose doubled area is below this fraction of its longest edge squared has no
// normal that survives rounding (collinear or coincident corners).
constexpr double kDegenerateRatio = 1e-12;

struct DirectedEdge {
  int lo, hi;    // sorted vertex indices
  bool forward;  // the triangle runs lo -> hi
  std::size_t triangle;
  int k;  // edge k of the triangle
};

std::string vertexText(const std::vector<Eigen::Vector3d> &v, int i) {
  std::ostringstream s;
  s << "vertex " << i + 1 << " (" << v[i].x() << ", " << v[i].y() << ", " << v[i].z() << ")";
  return s.str();
}

}  // namespace

std::string SurfaceSource::where(std::size_t triangle) const {
  if (triangle >= locations.size()) return file;
  if (byteOffsets) return file + ": byte " + std::to_string(locations[triangle]);
  return file + ":" + std::to_string(locations[triangle]);
}

TriangleSurface::TriangleSurface(std::vector<Eigen::Vector3d> vertices, std::vector<Triangle> triangles,
                                 SurfaceSource source)
    : vertices_(std::move(vertices)), triangles_(std::move(triangles)), source_(std::move(source)) {
  if (triangles_.empty()) throw SurfaceError(source_.file + ": no triangles");
  checkTriangles();
  checkEdges();
  computePseudonormals();
}

void TriangleSurface::checkTriangles() {
  const int n = static_cast<int>(vertices_.size());
  normals_.resize(triangles_.size());
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const Triangle &tri = triangles_[t];
    for (int i : tri) {
      if (i < 0 || i >= n) {
        throw SurfaceError(source_.where(t) + ": triangle " + std::to_string(t + 1) + " refers to vertex " +
                           std::to_string(i + 1) + "; the file has vertices 1 to " + std::to_string(n));
      }
    }
    const Eigen::Vector3d a = vertices_[tri[0]], b = vertices_[tri[1]], c = vertices_[tri[2]];
    const Eigen::Vector3d cross = (b - a).cross(c - a);
    const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] ||
        !(cross.norm() > kDegenerateRatio * longest)) {
      throw SurfaceError(source_.where(t) + ": triangle " + std::to_string(t + 1) +
                         " is degenerate (zero area): " + vertexText(vertices_, tri[0]) + ", " +
                         vertexText(vertices_, tri[1]) + ", " + vertexText(vertices_, tri[2]));
    }
    normals_[t] = cross.normalized();
  }
}

// Sorted by the undirected edge, the triangles sharing an edge are neighbours: more than two is
// non-manifold; two that run it the same way are inconsistently oriented.
void TriangleSurface::checkEdges() {
  std::vector<DirectedEdge> edges;
  edges.reserve(3 * triangles_.size());
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int i = triangles_[t][k], j = triangles_[t][(k + 1) % 3];
      edges.push_back({std::min(i, j), std::max(i, j), i < j, t, k});
    }
  }
  std::sort(edges.begin(), edges.end(), [](const DirectedEdge &p, const DirectedEdge &q) {
    return std::tie(p.lo, p.hi, p.triangle) < std::tie(q.lo, q.hi, q.triangle);
  });
  edgeNormals_.assign(triangles_.size(),
                      {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()});
  freeEdges_.assign(triangles_.size(), {false, false, false});
  freeVertices_.assign(vertices_.size(), false);
  boundaryEdges_ = 0;
  for (std::size_t first = 0; first < edges.size();) {
    std::size_t last = first;
    while (last < edges.size() && edges[last].lo == edges[first].lo && edges[last].hi == edges[first].hi)
      ++last;
    const DirectedEdge &p = edges[first];
    const std::string edgeText =
        "the edge between " + vertexText(vertices_, p.lo) + " and " + vertexText(vertices_, p.hi);
    if (last - first > 2) {
      std::string list;
      for (std::size_t e = first; e < last; ++e) {
        list += (e > first ? ", " : "") + std::to_string(edges[e].triangle + 1) + " (" +
                source_.where(edges[e].triangle) + ")";
      }
      throw SurfaceError(source_.where(edges[first + 2].triangle) + ": non-manifold surface: " + edgeText +
                         " is shared by " + std::to_string(last - first) + " triangles, " + list +
                         "; at most 2 may share an edge");
    }
    if (last - first == 2) {
      const DirectedEdge &q = edges[first + 1];
      if (p.forward == q.forward) {
        throw SurfaceError(
            source_.where(q.triangle) + ": inconsistent orientation: triangles " +
            std::to_string(p.triangle + 1) + " (" + source_.where(p.triangle) + ") and " +
            std::to_string(q.triangle + 1) + " run " + edgeText +
            " in the same direction; neighbours must run a shared edge in opposite directions");
      }
      const Eigen::Vector3d sum = normals_[p.triangle] + normals_[q.triangle];
      edgeNormals_[p.triangle][p.k] = sum;
      edgeNormals_[q.triangle][q.k] = sum;
    } else {
      edgeNormals_[p.triangle][p.k] = normals_[p.triangle];
      freeEdges_[p.triangle][p.k] = true;
      freeVertices_[p.lo] = freeVertices_[p.hi] = true;
      ++boundaryEdges_;
    }
    first = last;
  }
}

void TriangleSurface::computePseudonormals() {
  vertexNormals_.assign(vertices_.size(), Eigen::Vector3d::Zero());
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d p = corner(t, k);
      const Eigen::Vector3d u = (corner(t, (k + 1) % 3) - p).normalized();
      const Eigen::Vector3d w = (corner(t, (k + 2) % 3) - p).normalized();
      const double angle = std::acos(std::clamp(u.dot(w), -1.0, 1.0));
      vertexNormals_[triangles_[t][k]] += angle * normals_[t];
    }
  }
}

double TriangleSurface::enclosedVolume() const {
  double sixV = 0;
  for (const Triangle &t : triangles_) sixV += vertices_[t[0]].dot(vertices_[t[1]].cross(vertices_[t[2]]));
  return sixV / 6.0;
}

double TriangleSurface::area() const {
  double twiceA = 0;
  for (const Triangle &t : triangles_) {
    twiceA += (vertices_[t[1]] - vertices_[t[0]]).cross(vertices_[t[2]] - vertices_[t[0]]).norm();
  }
  return twiceA / 2.0;
}

TriangleSurface TriangleSurface::flipped() const {
  std::vector<Triangle> reversed = triangles_;
  for (Triangle &t : reversed) std::swap(t[1], t[2]);
  return TriangleSurface(vertices_, std::move(reversed), source_);
}

}  // namespace glossa::contact
