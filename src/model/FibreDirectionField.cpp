#include "model/FibreDirectionField.hpp"

#include "fem/HexShape.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace glossa::model {

namespace {
std::string describe(const Eigen::Vector3d &v) {
  std::ostringstream s;
  s << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  return s.str();
}
} // namespace

std::vector<Eigen::Vector3d> constantDirections(const Eigen::Vector3d &direction, std::size_t count) {
  if (!(direction.norm() > 0.0)) throw std::invalid_argument("the fibre direction is zero");
  return std::vector<Eigen::Vector3d>(count, direction.normalized());
}

Eigen::Vector3d radialFanDirection(const Eigen::Vector3d &x, const Eigen::Vector3d &centre,
                                   const Eigen::Vector3d &planeNormal) {
  const bool inPlane = planeNormal.norm() > 0.0;
  Eigen::Vector3d d = x - centre;
  if (inPlane) d -= d.dot(planeNormal.normalized()) * planeNormal.normalized();
  // A point closer to the centre than 1e-9 of its distance scale has no radial direction.
  if (!(d.norm() > 1e-9 * std::max(x.norm(), centre.norm())))
    throw std::invalid_argument(describe(x) + " lies on the fan's centre" + (inPlane ? " line" : "") +
                                ": its radial direction is undefined");
  return d.normalized();
}

std::vector<Eigen::Vector3d> radialFanDirections(const mesh::HexMesh &mesh, const std::vector<mesh::ElementId> &elements,
                                                 const Eigen::Vector3d &centre, const Eigen::Vector3d &planeNormal) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(elements.size());
  for (const auto e : elements) {
    const Eigen::Vector3d centroid = mesh.elementCoordinates(e).colwise().mean().transpose();
    try {
      out.push_back(radialFanDirection(centroid, centre, planeNormal));
    } catch (const std::invalid_argument &why) {
      throw std::invalid_argument("element " + std::to_string(e) + ", centroid " + why.what());
    }
  }
  return out;
}

Eigen::Vector3d nearestSegmentDirection(const Polylines &polylines, const Eigen::Vector3d &x) {
  double best = std::numeric_limits<double>::infinity();
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  for (const auto &line : polylines)
    for (std::size_t k = 0; k + 1 < line.size(); ++k) {
      const Eigen::Vector3d a = line[k], d = line[k + 1] - line[k];
      const double length2 = d.squaredNorm();
      if (!(length2 > 0.0)) continue;
      const double s = std::clamp((x - a).dot(d) / length2, 0.0, 1.0);
      // At a clamped end the nearest point is that vertex itself, not a + s d rounded (a + 1 d can
      // miss the next vertex by an ulp): a vertex shared by two segments is then exactly as near
      // from both, and the tie goes to the first, as documented, whatever the rounding.
      const Eigen::Vector3d foot = s <= 0.0   ? a
                                   : s >= 1.0 ? Eigen::Vector3d(line[k + 1])
                                              : Eigen::Vector3d(a + s * d);
      const double distance = (foot - x).norm();
      if (distance < best) {
        best = distance;
        direction = d / std::sqrt(length2);
      }
    }
  if (!(best < std::numeric_limits<double>::infinity()))
    throw std::invalid_argument("the fibre polylines have no segment of positive length");
  return direction;
}

std::vector<Eigen::Vector3d> polylineDirections(const mesh::HexMesh &mesh, const std::vector<mesh::ElementId> &elements,
                                                const Polylines &polylines) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(elements.size());
  for (const auto e : elements)
    out.push_back(nearestSegmentDirection(polylines, mesh.elementCoordinates(e).colwise().mean().transpose()));
  return out;
}

std::vector<PointDirections> polylinePointDirections(const mesh::HexMesh &mesh,
                                                     const std::vector<mesh::ElementId> &elements,
                                                     const Polylines &polylines) {
  std::vector<PointDirections> out;
  out.reserve(elements.size());
  const auto &points = fem::gaussHex2();
  for (const auto e : elements) {
    const fem::NodeMatrix X = mesh.elementCoordinates(e);
    PointDirections N;
    for (int q = 0; q < 8; ++q)
      N[q] = nearestSegmentDirection(polylines, X.transpose() * fem::hexShape(points[q].xi));
    out.push_back(N);
  }
  return out;
}

std::vector<Eigen::Vector3d> directionsFromFile(const std::filesystem::path &file, DirectionsPer per,
                                                const mesh::HexMesh &mesh,
                                                const std::vector<mesh::ElementId> &elements) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot open the fibre direction file");
  const std::size_t count = per == DirectionsPer::Element ? mesh.numElements() : mesh.nodes.size();
  const char *what = per == DirectionsPer::Element ? "element" : "node";
  std::vector<Eigen::Vector3d> vectors(count, Eigen::Vector3d::Zero());
  std::vector<char> given(count, 0);
  std::string line;
  for (int lineNumber = 1; std::getline(in, line); ++lineNumber) {
    const auto where = [&] { return file.string() + ":" + std::to_string(lineNumber) + ": "; };
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    for (char &c : line)
      if (c == ',' || c == '\t' || c == ';') c = ' ';
    std::istringstream fields(line);
    long long id = 0;
    Eigen::Vector3d v;
    if (!(fields >> id)) {
      if (line.find_first_not_of(" \r") == std::string::npos) continue; // blank
      throw std::runtime_error(where() + "expected 'id nx ny nz', got '" + line + "'");
    }
    std::string rest;
    if (!(fields >> v.x() >> v.y() >> v.z()) || (fields >> rest))
      throw std::runtime_error(where() + "expected 'id nx ny nz', got '" + line + "'");
    if (id < 0 || static_cast<std::size_t>(id) >= count)
      throw std::runtime_error(where() + what + " id " + std::to_string(id) + " is out of range [0, " +
                               std::to_string(count - 1) + "]");
    if (given[id]) throw std::runtime_error(where() + what + " " + std::to_string(id) + " is given twice");
    if (!(v.norm() > 0.0) || !v.allFinite())
      throw std::runtime_error(where() + "the direction of " + what + " " + std::to_string(id) + " is zero or not finite");
    vectors[id] = v.normalized();
    given[id] = 1;
  }
  std::vector<Eigen::Vector3d> out;
  out.reserve(elements.size());
  for (const auto e : elements) {
    if (per == DirectionsPer::Element) {
      if (!given[e]) throw std::runtime_error(file.string() + ": no direction for element " + std::to_string(e));
      out.push_back(vectors[e]);
      continue;
    }
    Eigen::Vector3d sum = Eigen::Vector3d::Zero(), first = Eigen::Vector3d::Zero();
    for (const auto node : mesh.elements[e]) {
      if (!given[node])
        throw std::runtime_error(file.string() + ": no direction for node " + std::to_string(node) + " of element " +
                                 std::to_string(e));
      const Eigen::Vector3d &v = vectors[node];
      if (first.isZero()) first = v;
      sum += v.dot(first) < 0.0 ? -v : v; // axial: align signs before averaging
    }
    if (!(sum.norm() > 1e-12))
      throw std::runtime_error(file.string() + ": the node directions of element " + std::to_string(e) +
                               " cancel out");
    out.push_back(sum.normalized());
  }
  return out;
}

} // namespace glossa::model
