#pragma once
// A rigid obstacle given by a triangulated surface (OBJ, STL): the closest point by CGAL's AABB
// tree, built once, then the contact quantities on the triangle it finds (SurfaceProjection:
// the face normal on a triangle's interior, the direction to x on an edge or corner), or with
// normals interpolated from the vertices (SmoothedProjection), which turn continuously from one
// triangle to the next. The normals must already point to the body's side
// (SurfaceOrientation). CGAL stays inside this class's source file: it is slow to compile.

#include <memory>

#include "contact/Obstacle.hpp"
#include "contact/TriangleSurface.hpp"

namespace glossa::contact {

// faceted: each triangle's own normal (and the direction to x beyond an edge or corner);
// smoothed: the normal interpolated from unit vertex normals (doc/contact.md, "Smoothed normals").
enum class NormalField { faceted, smoothed };

class TriangulatedObstacle : public Obstacle {
 public:
  explicit TriangulatedObstacle(TriangleSurface surface, NormalField field = NormalField::faceted);
  ~TriangulatedObstacle() override;
  TriangulatedObstacle(const TriangulatedObstacle &) = delete;
  TriangulatedObstacle &operator=(const TriangulatedObstacle &) = delete;

  std::optional<ClosestPoint> closest(const Eigen::Vector3d &x, double searchRadius) const override;
  const TriangleSurface &surface() const { return surface_; }

 private:
  struct Search;
  TriangleSurface surface_;
  NormalField field_;
  std::unique_ptr<Search> search_;
};

}  // namespace glossa::contact
