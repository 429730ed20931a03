#include "airway/Centreline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "airway/PlaneCut.hpp"

namespace glossa::airway {

namespace {
// A polyline with its cumulative arc length, for points by arc length and the nearest point.
struct ArcCurve {
  std::vector<Eigen::Vector3d> points;
  std::vector<double> s;

  explicit ArcCurve(const CutCurve &c) : points(c.points) {
    if (c.closed && !points.empty()) points.push_back(points.front());
    s.assign(points.size(), 0.0);
    for (std::size_t k = 1; k < points.size(); ++k) s[k] = s[k - 1] + (points[k] - points[k - 1]).norm();
  }
  Eigen::Vector3d at(double arc) const {
    const auto it = std::upper_bound(s.begin(), s.end(), arc);
    const std::size_t k = std::clamp<std::size_t>(static_cast<std::size_t>(it - s.begin()), 1, s.size() - 1);
    const double len = s[k] - s[k - 1];
    const double f = len > 0.0 ? std::clamp((arc - s[k - 1]) / len, 0.0, 1.0) : 0.0;
    return points[k - 1] + f * (points[k] - points[k - 1]);
  }
  // The nearest point to x and its arc length.
  std::pair<Eigen::Vector3d, double> nearest(const Eigen::Vector3d &x) const {
    std::pair<Eigen::Vector3d, double> best{points.front(), 0.0};
    double bestDistance = (points.front() - x).norm();
    for (std::size_t k = 1; k < points.size(); ++k) {
      const Eigen::Vector3d ab = points[k] - points[k - 1];
      const double len2 = ab.squaredNorm();
      const double f = len2 > 0.0 ? std::clamp((x - points[k - 1]).dot(ab) / len2, 0.0, 1.0) : 0.0;
      const Eigen::Vector3d p = points[k - 1] + f * ab;
      if ((p - x).norm() < bestDistance) {
        bestDistance = (p - x).norm();
        best = {p, s[k - 1] + f * (s[k] - s[k - 1])};
      }
    }
    return best;
  }
};
}  // namespace

Centreline buildCentreline(const TriangleSet &tongue, const TriangleSet &wall, const CentrelineSettings &settings) {
  if (settings.sections < 1) throw std::invalid_argument("the airway needs at least one section");
  SectionPlane mid;
  mid.origin = settings.midsagittalPoint;
  mid.normal = settings.lateralAxis.normalized();
  const std::vector<CutCurve> tongueCuts = cutSurface(tongue.vertices, tongue.triangles, mid);
  const std::vector<CutCurve> wallCuts = cutSurface(wall.vertices, wall.triangles, mid);
  const CutCurve *tongueCurve = nearestCurve(tongueCuts, settings.start);
  if (!tongueCurve || tongueCurve->points.size() < 2)
    throw std::invalid_argument("the midsagittal plane does not cut the tongue's airway surface");
  if (wallCuts.empty()) throw std::invalid_argument("the midsagittal plane does not cut the wall surface");
  const ArcCurve t(*tongueCurve);
  std::vector<ArcCurve> walls;
  for (const auto &c : wallCuts)
    if (c.points.size() >= 2) walls.emplace_back(c);
  const double sA = t.nearest(settings.start).second, sB = t.nearest(settings.end).second;
  if (sA == sB)
    throw std::invalid_argument("the start and end points are nearest to the same point of the tongue's midsagittal curve");
  Centreline out;
  const int n = settings.sections;
  std::vector<Eigen::Vector3d> centre;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d ti = t.at(sA + (i + 0.5) / n * (sB - sA));
    Eigen::Vector3d wi = walls.front().points.front();
    double best = std::numeric_limits<double>::infinity();
    for (const auto &w : walls) {
      const Eigen::Vector3d p = w.nearest(ti).first;
      if ((p - ti).norm() < best) {
        best = (p - ti).norm();
        wi = p;
      }
    }
    out.tonguePoints.push_back(ti);
    out.wallPoints.push_back(wi);
    centre.push_back(0.5 * (ti + wi));
  }
  for (int i = 0; i < n; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    Eigen::Vector3d d;
    if (n == 1)  // no neighbour: the tongue curve's own direction
      d = t.at(sA + 0.5 * (sB - sA) + 1e-3 * (sB - sA)) - t.at(sA + 0.5 * (sB - sA) - 1e-3 * (sB - sA));
    else
      d = centre[std::min(k + 1, centre.size() - 1)] - centre[k == 0 ? 0 : k - 1];
    d -= d.dot(mid.normal) * mid.normal;
    out.planes.push_back(makeSectionPlane(centre[k], d, mid.normal, out.wallPoints[k] - out.tonguePoints[k]));
    out.arcLength.push_back(k == 0 ? 0.0 : out.arcLength[k - 1] + (centre[k] - centre[k - 1]).norm());
  }
  return out;
}

}  // namespace glossa::airway
