#pragma once
// A rigid obstacle given by a triangulated surface (OBJ, STL): the closest point by CGAL's AABB
// tree, built once, then the contact quantities on the triangle it finds (SurfaceProjection:
// the face normal on a triangle's interior, the direction to x on an edge or corner), or with
// normals interpolated from the vertices (SmoothedProjection), which turn continuously from one
// triangle to the next, or on an implicit surface through the vertices (ImplicitSurface; its
// vertices found by CGAL's k-d tree). The normals must already point to the body's side
// (SurfaceOrientation). CGAL stays inside this class's source file: it is slow to compile.

#include <memory>

#include "contact/Obstacle.hpp"
#include "contact/TriangleSurface.hpp"

namespace glossa::contact {

// faceted: each triangle's own normal (and the direction to x beyond an edge or corner);
// smoothed: the normal interpolated from unit vertex normals (doc/contact.md, "Smoothed normals");
// implicit: the gap and normal of a smooth implicit surface through the vertices
// (ImplicitSurface; doc/contact.md, "Implicit surface"), whose contact tangent is continuous.
enum class NormalField { faceted, smoothed, implicit };

class TriangulatedObstacle : public Obstacle {
 public:
  // implicitRadius: the implicit surface's support radius [m]; 0: kImplicitRadiusInEdges mean
  // edge lengths. Unused by the other fields.
  explicit TriangulatedObstacle(TriangleSurface surface, NormalField field = NormalField::faceted,
                                double implicitRadius = 0.0);
  ~TriangulatedObstacle() override;
  TriangulatedObstacle(const TriangulatedObstacle &) = delete;
  TriangulatedObstacle &operator=(const TriangulatedObstacle &) = delete;

  std::optional<ClosestPoint> closest(const Eigen::Vector3d &x, double searchRadius) const override;
  const TriangleSurface &surface() const { return surface_; }
  double implicitRadius() const { return implicitRadius_; }

 private:
  ClosestPoint onImplicitSurface(std::size_t triangle, const Eigen::Vector3d &x) const;
  struct Search;
  TriangleSurface surface_;
  NormalField field_;
  double implicitRadius_ = 0.0;
  std::unique_ptr<Search> search_;
};

}  // namespace glossa::contact
