#pragma once
// A rigid obstacle's surface as triangles: vertices, triangles and their unit normals (from the
// winding, right-hand rule), checked on construction. An open boundary is allowed (the palate is
// an open sheet); a degenerate triangle, an edge shared by more than two triangles, and two
// triangles that run a shared edge in the same direction (inconsistent orientation) are refused
// with a SurfaceError naming the file, the line (or byte offset) and the triangles and vertices.
// Also the pseudonormals that sign the gap on an edge or a corner (Baerentzen & Aanaes, IEEE
// TVCG 11(3), 2005): an edge's is the sum of its triangles' normals, a vertex's the sum weighted
// by the triangles' angles at it.

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace glossa::contact {

// Where each triangle came from, for messages: a line of a text file, or the byte offset of its
// record in a binary one.
struct SurfaceSource {
  std::string file;
  bool byteOffsets = false;
  std::vector<std::size_t> locations;  // per triangle; empty for a surface built in code
  // "file:LINE", "file: byte N", or "file" when the triangle has no location.
  std::string where(std::size_t triangle) const;
};

class TriangleSurface {
 public:
  using Triangle = std::array<int, 3>;  // 0-based vertex indices

  // Checks the triangles (indices in range, not degenerate, manifold edges, consistent
  // orientation); throws SurfaceError.
  TriangleSurface(std::vector<Eigen::Vector3d> vertices, std::vector<Triangle> triangles,
                  SurfaceSource source);

  const std::vector<Eigen::Vector3d> &vertices() const { return vertices_; }
  const std::vector<Triangle> &triangles() const { return triangles_; }
  std::size_t numTriangles() const { return triangles_.size(); }
  const Eigen::Vector3d &normal(std::size_t t) const { return normals_[t]; }
  const SurfaceSource &source() const { return source_; }

  // Edges with a single triangle; 0 for a closed surface.
  std::size_t boundaryEdges() const { return boundaryEdges_; }
  bool isClosed() const { return boundaryEdges_ == 0; }
  // Signed volume enclosed (divergence theorem); positive when the normals point out. Only a
  // closed surface encloses one.
  double enclosedVolume() const;
  double area() const;
  // The same triangles wound the other way: every normal reversed.
  TriangleSurface flipped() const;

  // Pseudonormals (not unit): of edge k (corner k to k+1) of triangle t, and of vertex v.
  const Eigen::Vector3d &edgePseudonormal(std::size_t t, int k) const { return edgeNormals_[t][k]; }
  const Eigen::Vector3d &vertexPseudonormal(std::size_t v) const { return vertexNormals_[v]; }
  // On the free boundary of an open surface: edge k of triangle t has no neighbour; vertex v
  // lies on such an edge.
  bool onFreeBoundary(std::size_t t, int k) const { return freeEdges_[t][k]; }
  bool onFreeBoundary(std::size_t v) const { return freeVertices_[v]; }
  Eigen::Vector3d corner(std::size_t t, int k) const { return vertices_[triangles_[t][k]]; }

 private:
  void checkTriangles();
  void checkEdges();
  void computePseudonormals();

  std::vector<Eigen::Vector3d> vertices_;
  std::vector<Triangle> triangles_;
  SurfaceSource source_;
  std::vector<Eigen::Vector3d> normals_;
  std::vector<std::array<Eigen::Vector3d, 3>> edgeNormals_;
  std::vector<Eigen::Vector3d> vertexNormals_;
  std::vector<std::array<bool, 3>> freeEdges_;
  std::vector<bool> freeVertices_;
  std::size_t boundaryEdges_ = 0;
};

}  // namespace glossa::contact
