#include "airway/SectionPlane.hpp"

#include <Eigen/Geometry>
#include <stdexcept>

namespace glossa::airway {

SectionPlane makeSectionPlane(const Eigen::Vector3d &origin, const Eigen::Vector3d &normal,
                              const Eigen::Vector3d &lateral, const Eigen::Vector3d &towardWall) {
  if (normal.norm() == 0.0) throw std::invalid_argument("a section plane needs a nonzero normal");
  SectionPlane p;
  p.origin = origin;
  p.normal = normal.normalized();
  const Eigen::Vector3d l = lateral - lateral.dot(p.normal) * p.normal;
  // Below this the lateral axis is (nearly) the normal, and the in-plane axes are undefined.
  if (l.norm() <= 1e-9 * lateral.norm())
    throw std::invalid_argument("a section plane's normal is parallel to the lateral axis");
  p.lateral = l.normalized();
  p.depth = p.normal.cross(p.lateral);
  // The lateral axis keeps its sense (u runs the same way in every section); only the area's
  // magnitude depends on the axes, not their handedness.
  if (p.depth.dot(towardWall) < 0.0) p.depth = -p.depth;
  return p;
}

}  // namespace glossa::airway
