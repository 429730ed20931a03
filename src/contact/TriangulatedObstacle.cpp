#include "contact/TriangulatedObstacle.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Iso_cuboid_3.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <vector>

#include "contact/SmoothedProjection.hpp"
#include "contact/SurfaceProjection.hpp"

namespace glossa::contact {

namespace {
using Kernel = CGAL::Simple_cartesian<double>;
using Triangles = std::vector<Kernel::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Kernel::Point_3 point(const Eigen::Vector3d &x) { return {x.x(), x.y(), x.z()}; }
}  // namespace

// The tree refers to the triangles by iterator: both live here, never moved once built.
struct TriangulatedObstacle::Search {
  Triangles triangles;
  Tree tree;
};

TriangulatedObstacle::TriangulatedObstacle(TriangleSurface surface, NormalField field)
    : surface_(std::move(surface)), field_(field), search_(std::make_unique<Search>()) {
  search_->triangles.reserve(surface_.numTriangles());
  for (std::size_t t = 0; t < surface_.numTriangles(); ++t) {
    search_->triangles.emplace_back(point(surface_.corner(t, 0)), point(surface_.corner(t, 1)),
                                    point(surface_.corner(t, 2)));
  }
  search_->tree.insert(search_->triangles.cbegin(), search_->triangles.cend());
  search_->tree.build();
  // Built now rather than on the first query, so that queries only read the tree.
  search_->tree.accelerate_distance_queries();
}

TriangulatedObstacle::~TriangulatedObstacle() = default;

std::optional<ClosestPoint> TriangulatedObstacle::closest(const Eigen::Vector3d &x,
                                                          double searchRadius) const {
  // Most of the body's surface is far from the obstacle: the cube around the ball of the search
  // radius is rejected on the tree's boxes alone, far cheaper than a closest-point query. (Not
  // CGAL's Sphere_3: against a triangle it is the sphere's surface, which misses a triangle
  // inside the ball.)
  if (std::isfinite(searchRadius)) {
    const Eigen::Vector3d r = Eigen::Vector3d::Constant(searchRadius);
    if (!search_->tree.do_intersect(Kernel::Iso_cuboid_3(point(x - r), point(x + r)))) return std::nullopt;
  }
  const auto [p, id] = search_->tree.closest_point_and_primitive(point(x));
  if (CGAL::squared_distance(p, point(x)) > searchRadius * searchRadius) return std::nullopt;
  const auto triangle = static_cast<std::size_t>(id - search_->triangles.cbegin());
  return field_ == NormalField::smoothed ? projectOnSmoothedTriangle(surface_, triangle, x)
                                         : projectOnTriangle(surface_, triangle, x);
}

}  // namespace glossa::contact
