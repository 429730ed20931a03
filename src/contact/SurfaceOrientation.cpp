#include "contact/SurfaceOrientation.hpp"

#include <sstream>

#include "contact/SurfaceError.hpp"
#include "contact/SurfaceProjection.hpp"

namespace glossa::contact {

TriangleSurface orientNormals(TriangleSurface surface, NormalSide side, const Eigen::Vector3d &bodyPoint) {
  switch (side) {
    case NormalSide::AsStored:
      return surface;
    case NormalSide::Outward:
      if (!surface.isClosed()) {
        throw SurfaceError(surface.source().file +
                           ": outward normals need a closed surface, and this one has " +
                           std::to_string(surface.boundaryEdges()) +
                           " boundary edges (an open sheet): give a point on the body's side instead");
      }
      return surface.enclosedVolume() < 0 ? surface.flipped() : surface;
    case NormalSide::TowardPoint: {
      bool beside = false;
      const ClosestPoint cp =
          projectOnTriangle(surface, closestTriangleByScan(surface, bodyPoint), bodyPoint, &beside);
      if ((bodyPoint - cp.point).norm() == 0 || beside) {
        std::ostringstream s;
        s << surface.source().file << ": the point (" << bodyPoint.x() << ", " << bodyPoint.y() << ", "
          << bodyPoint.z() << ") given on the body's side "
          << (beside ? "lies beside the surface's free edge" : "lies on the surface itself")
          << ", so it is on neither side: give a point that faces the surface";
        throw SurfaceError(s.str());
      }
      return cp.gap < 0 ? surface.flipped() : surface;
    }
  }
  return surface;
}

}  // namespace glossa::contact
