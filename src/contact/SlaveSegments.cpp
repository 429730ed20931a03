#include "contact/SlaveSegments.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace glossa::contact {

namespace {

using Polygon = std::vector<Eigen::Vector2d>;  // convex, in order

// A line n . x = c with unit n, the cut along one projected master edge.
struct Line {
  Eigen::Vector2d n;
  double c = 0;
};

// The two parts of a convex polygon on either side of a line (either may be empty).
std::array<Polygon, 2> split(const Polygon &p, const Line &line) {
  std::array<Polygon, 2> parts;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector2d &a = p[i], &b = p[(i + 1) % p.size()];
    const double da = line.n.dot(a) - line.c, db = line.n.dot(b) - line.c;
    parts[da < 0 ? 0 : 1].push_back(a);
    if ((da < 0) != (db < 0)) {
      const Eigen::Vector2d x = a + (b - a) * (da / (da - db));
      parts[0].push_back(x);
      parts[1].push_back(x);
    }
  }
  // A vertex on the line comes back as its own crossing: keep it once.
  for (Polygon &part : parts) {
    Polygon kept;
    for (const Eigen::Vector2d &v : part)
      if (kept.empty() || (v - kept.back()).norm() > 1e-14) kept.push_back(v);
    while (kept.size() > 1 && (kept.front() - kept.back()).norm() <= 1e-14) kept.pop_back();
    part = std::move(kept);
  }
  return parts;
}

double area(const Polygon &p) {
  double twice = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector2d &a = p[i], &b = p[(i + 1) % p.size()];
    twice += a(0) * b(1) - a(1) * b(0);
  }
  return 0.5 * std::abs(twice);
}

// The distinct lines through the projected master edges (a structured master repeats each line
// along its faces; a line is kept once). Lines that miss the square are kept too: they cut nothing.
std::vector<Line> masterEdgeLines(const loads::FaceNodes &slaveX,
                                  const std::vector<loads::FaceNodes> &masterX) {
  std::vector<Line> lines;
  for (const loads::FaceNodes &m : masterX) {
    std::array<Eigen::Vector2d, 4> st;
    bool projected = true;
    for (int a = 0; a < 4; ++a) {
      const auto p = projectOntoFace(slaveX, m.row(a).transpose());
      if (!p) {
        projected = false;
        break;
      }
      st[static_cast<std::size_t>(a)] = p->st;
    }
    if (!projected) continue;
    for (std::size_t a = 0; a < 4; ++a) {
      const Eigen::Vector2d d = st[(a + 1) % 4] - st[a];
      if (d.norm() < 1e-12) continue;
      Line line{Eigen::Vector2d(-d(1), d(0)).normalized(), 0.0};
      if (line.n(0) < 0 || (line.n(0) == 0 && line.n(1) < 0)) line.n = -line.n;  // one sign per direction
      line.c = line.n.dot(st[a]);
      const bool known = std::any_of(lines.begin(), lines.end(), [&](const Line &l) {
        return (l.n - line.n).norm() < 1e-9 && std::abs(l.c - line.c) < 1e-9;
      });
      if (!known) lines.push_back(line);
    }
  }
  return lines;
}

}  // namespace

std::vector<SlavePoint> segmentedSlavePoints(const loads::FaceNodes &slaveX,
                                             const std::vector<loads::FaceNodes> &masterX) {
  std::vector<Polygon> cells{
      {Eigen::Vector2d(-1, -1), Eigen::Vector2d(1, -1), Eigen::Vector2d(1, 1), Eigen::Vector2d(-1, 1)}};
  for (const Line &line : masterEdgeLines(slaveX, masterX)) {
    std::vector<Polygon> next;
    for (const Polygon &cell : cells)
      for (Polygon &part : split(cell, line))
        // A sliver thinner than round-off is dropped; its area (below 1e-24) is nothing to integrate.
        if (part.size() >= 3 && area(part) > 1e-24) next.push_back(std::move(part));
    cells = std::move(next);
  }
  // Dunavant's 6-point rule of degree 4 on a triangle (barycentric coordinates, weights summing to 1).
  constexpr double a = 0.445948490915965, b = 0.091576213509771;
  constexpr double wa = 0.223381589678011, wb = 0.109951743655322;
  const std::array<std::array<double, 3>, 6> bary{{{a, a, 1 - 2 * a},
                                                   {a, 1 - 2 * a, a},
                                                   {1 - 2 * a, a, a},
                                                   {b, b, 1 - 2 * b},
                                                   {b, 1 - 2 * b, b},
                                                   {1 - 2 * b, b, b}}};
  const std::array<double, 6> weight{wa, wa, wa, wb, wb, wb};
  std::vector<SlavePoint> points;
  for (const Polygon &cell : cells)
    for (std::size_t k = 1; k + 1 < cell.size(); ++k) {
      const Polygon triangle{cell[0], cell[k], cell[k + 1]};
      const double A = area(triangle);
      if (A <= 1e-24) continue;
      for (std::size_t q = 0; q < 6; ++q)
        points.push_back(
            {bary[q][0] * triangle[0] + bary[q][1] * triangle[1] + bary[q][2] * triangle[2], weight[q] * A});
    }
  return points;
}

}  // namespace glossa::contact
