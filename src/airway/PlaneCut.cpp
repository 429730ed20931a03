#include "airway/PlaneCut.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <utility>

namespace glossa::airway {

namespace {
using EdgeKey = std::pair<int, int>;  // vertex indices, smaller first

EdgeKey edgeKey(int a, int b) { return a < b ? EdgeKey{a, b} : EdgeKey{b, a}; }

double segmentDistance(const Eigen::Vector3d &a, const Eigen::Vector3d &b, const Eigen::Vector3d &x) {
  const Eigen::Vector3d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((x - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - x).norm();
}
}  // namespace

double CutCurve::distanceTo(const Eigen::Vector3d &x) const {
  double best = std::numeric_limits<double>::infinity();
  if (points.size() == 1) return (points[0] - x).norm();
  const std::size_t n = points.size();
  for (std::size_t k = 0; k + 1 < n + (closed ? 1 : 0); ++k)
    best = std::min(best, segmentDistance(points[k], points[(k + 1) % n], x));
  return best;
}

std::vector<CutCurve> cutSurface(const std::vector<Eigen::Vector3d> &vertices,
                                 const std::vector<std::array<int, 3>> &triangles, const SectionPlane &plane) {
  std::vector<double> side(vertices.size());
  for (std::size_t v = 0; v < vertices.size(); ++v) side[v] = plane.distance(vertices[v]);
  auto positive = [&](int v) { return side[static_cast<std::size_t>(v)] >= 0.0; };
  // Each crossing edge's point, and the (at most two, on a manifold surface) segments through it.
  std::map<EdgeKey, Eigen::Vector3d> crossing;
  std::map<EdgeKey, std::vector<std::size_t>> segmentsAt;
  std::vector<std::array<EdgeKey, 2>> segments;
  for (const auto &t : triangles) {
    std::array<EdgeKey, 2> ends;
    int found = 0;
    for (int k = 0; k < 3; ++k) {
      const int a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
      if (positive(a) == positive(b)) continue;
      const EdgeKey key = edgeKey(a, b);
      // Interpolated from the key's own order, so both triangles of an edge get the same point.
      const double da = side[static_cast<std::size_t>(key.first)], db = side[static_cast<std::size_t>(key.second)];
      const double s = da / (da - db);
      crossing.try_emplace(key, vertices[static_cast<std::size_t>(key.first)] +
                                    s * (vertices[static_cast<std::size_t>(key.second)] -
                                         vertices[static_cast<std::size_t>(key.first)]));
      ends[static_cast<std::size_t>(found++)] = key;
    }
    if (found != 2) continue;  // a triangle wholly on one side
    for (const auto &key : ends) segmentsAt[key].push_back(segments.size());
    segments.push_back(ends);
  }
  // Chain the segments: start an open chain at an end point that only one segment uses, then
  // what is left forms closed loops.
  std::vector<bool> used(segments.size(), false);
  std::vector<CutCurve> curves;
  auto walk = [&](EdgeKey at, std::size_t first, CutCurve &curve) {
    std::size_t seg = first;
    curve.points.push_back(crossing.at(at));
    while (true) {
      used[seg] = true;
      at = segments[seg][0] == at ? segments[seg][1] : segments[seg][0];
      curve.points.push_back(crossing.at(at));
      std::size_t next = segments.size();
      for (std::size_t s : segmentsAt.at(at))
        if (!used[s]) next = s;
      if (next == segments.size()) return;
      seg = next;
    }
  };
  for (const auto &[key, segs] : segmentsAt)
    if (segs.size() == 1 && !used[segs[0]]) {
      CutCurve curve;
      walk(key, segs[0], curve);
      curves.push_back(std::move(curve));
    }
  for (std::size_t s = 0; s < segments.size(); ++s)
    if (!used[s]) {
      CutCurve curve;
      walk(segments[s][0], s, curve);
      curve.points.pop_back();  // back where it started
      curve.closed = true;
      curves.push_back(std::move(curve));
    }
  return curves;
}

const CutCurve *nearestCurve(const std::vector<CutCurve> &curves, const Eigen::Vector3d &x) {
  const CutCurve *best = nullptr;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (const auto &c : curves) {
    const double d = c.distanceTo(x);
    if (d < bestDistance) {
      bestDistance = d;
      best = &c;
    }
  }
  return best;
}

}  // namespace glossa::airway
