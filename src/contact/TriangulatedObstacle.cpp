#include "contact/TriangulatedObstacle.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Iso_cuboid_3.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

#include "contact/ImplicitSurface.hpp"
#include "contact/PointTriangle.hpp"
#include "contact/SmoothedProjection.hpp"
#include "contact/SurfaceProjection.hpp"

namespace glossa::contact {

namespace {
using Kernel = CGAL::Simple_cartesian<double>;
using Triangles = std::vector<Kernel::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
// The vertices by index, for the implicit surface's neighbours within its support radius.
using IndexedPoint = std::pair<Kernel::Point_3, int>;
using VertexTraits = CGAL::Search_traits_adapter<IndexedPoint, CGAL::First_of_pair_property_map<IndexedPoint>,
                                                 CGAL::Search_traits_3<Kernel>>;
using VertexTree = CGAL::Kd_tree<VertexTraits>;

Kernel::Point_3 point(const Eigen::Vector3d &x) { return {x.x(), x.y(), x.z()}; }
}  // namespace

// The tree refers to the triangles by iterator: both live here, never moved once built.
struct TriangulatedObstacle::Search {
  Triangles triangles;
  Tree tree;
  std::vector<IndexedPoint> vertices;
  VertexTree vertexTree;
  std::vector<Eigen::Vector3d> unitNormals;  // the implicit surface's N_i
};

TriangulatedObstacle::TriangulatedObstacle(TriangleSurface surface, NormalField field, double implicitRadius)
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
  if (field_ == NormalField::implicit) {
    implicitRadius_ = implicitRadius > 0.0 ? implicitRadius : kImplicitRadiusInEdges * meanEdgeLength(surface_);
    for (std::size_t v = 0; v < surface_.vertices().size(); ++v)
      search_->vertices.emplace_back(point(surface_.vertices()[v]), static_cast<int>(v));
    search_->vertexTree.insert(search_->vertices.begin(), search_->vertices.end());
    search_->vertexTree.build();
    search_->unitNormals = unitVertexNormals(surface_);
  }
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
  if (field_ == NormalField::implicit) return onImplicitSurface(triangle, x);
  return field_ == NormalField::smoothed ? projectOnSmoothedTriangle(surface_, triangle, x)
                                         : projectOnTriangle(surface_, triangle, x);
}

// Beside an open sheet's free boundary the faceted rule stands, as for smoothed normals; where
// the vertices' weights vanish (x farther from the surface than the support radius) the smoothed
// normals answer: such a point is apart either way.
ClosestPoint TriangulatedObstacle::onImplicitSurface(std::size_t triangle, const Eigen::Vector3d &x) const {
  const TriangleProjection pr =
      closestOnTriangle(x, surface_.corner(triangle, 0), surface_.corner(triangle, 1), surface_.corner(triangle, 2));
  if (onFreeBoundary(surface_, triangle, pr)) return projectOnTriangle(surface_, triangle, x);
  std::vector<IndexedPoint> found;
  search_->vertexTree.search(std::back_inserter(found),
                             CGAL::Fuzzy_sphere<VertexTraits>(point(x), implicitRadius_, 0.0));
  std::vector<int> neighbours;
  neighbours.reserve(found.size());
  for (const IndexedPoint &p : found) neighbours.push_back(p.second);
  // The tree's order is not the vertices': sorted, the sums are the same on every rank and run.
  std::sort(neighbours.begin(), neighbours.end());
  if (const auto cp = implicitSurfaceAt(surface_.vertices(), search_->unitNormals, neighbours, x, implicitRadius_))
    return *cp;
  return projectOnSmoothedTriangle(surface_, triangle, x);
}

}  // namespace glossa::contact
