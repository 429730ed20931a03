#include "airway/LumenArea.hpp"

#include <algorithm>
#include <limits>

namespace glossa::airway {

namespace {
struct Segment {
  Eigen::Vector2d a, b;  // a.x() < b.x(): segments along v alone have no extent in u and are left out
  double at(double u) const { return a.y() + (b.y() - a.y()) * (u - a.x()) / (b.x() - a.x()); }
  bool covers(double u) const { return a.x() <= u && u <= b.x(); }
};

std::vector<Segment> segmentsOf(const std::vector<Eigen::Vector2d> &points, bool closed) {
  std::vector<Segment> out;
  const std::size_t n = points.size();
  for (std::size_t k = 0; n > 1 && k + 1 < n + (closed ? 1 : 0); ++k) {
    Eigen::Vector2d a = points[k], b = points[(k + 1) % n];
    if (a.x() == b.x()) continue;
    if (a.x() > b.x()) std::swap(a, b);
    out.push_back({a, b});
  }
  return out;
}

// The u where two segments' lines cross, inside both, added to `breaks`.
void addCrossings(const std::vector<Segment> &segs, std::vector<double> &breaks) {
  for (std::size_t i = 0; i < segs.size(); ++i)
    for (std::size_t j = i + 1; j < segs.size(); ++j) {
      const double lo = std::max(segs[i].a.x(), segs[j].a.x()), hi = std::min(segs[i].b.x(), segs[j].b.x());
      if (!(lo < hi)) continue;
      const double dLo = segs[i].at(lo) - segs[j].at(lo), dHi = segs[i].at(hi) - segs[j].at(hi);
      if ((dLo < 0.0) != (dHi < 0.0) && dLo != 0.0 && dHi != 0.0) breaks.push_back(lo + (hi - lo) * dLo / (dLo - dHi));
    }
}

// The envelope's segment over (lo, hi), chosen at the interval's middle: the highest of the
// segments there (upper), or the lowest; nullptr if none covers it.
const Segment *envelopeAt(const std::vector<Segment> &segs, double u, bool upper) {
  const Segment *best = nullptr;
  for (const auto &s : segs)
    if (s.covers(u) && (!best || (upper ? s.at(u) > best->at(u) : s.at(u) < best->at(u)))) best = &s;
  return best;
}

std::pair<double, double> rangeOf(const std::vector<Segment> &segs) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto &s : segs) {
    lo = std::min(lo, s.a.x());
    hi = std::max(hi, s.b.x());
  }
  return {lo, hi};
}

// The measure of {u in [0, w] : g(u) <= c} for g linear from g0 to g1, and the integral of
// max(0, g) over it.
double widthBelow(double g0, double g1, double w, double c) {
  if (g0 <= c && g1 <= c) return w;
  if (g0 > c && g1 > c) return 0.0;
  const double s = (c - g0) / (g1 - g0);  // where g = c
  return g0 <= c ? s * w : (1.0 - s) * w;
}
double positivePart(double g0, double g1, double w) {
  if (g0 >= 0.0 && g1 >= 0.0) return 0.5 * (g0 + g1) * w;
  if (g0 <= 0.0 && g1 <= 0.0) return 0.0;
  const double s = g0 / (g0 - g1);  // where g = 0
  return g0 > 0.0 ? 0.5 * g0 * s * w : 0.5 * g1 * (1.0 - s) * w;
}
}  // namespace

LumenSection lumenBetween(const std::vector<Eigen::Vector2d> &tongue, bool tongueClosed,
                          const std::vector<Eigen::Vector2d> &wall, bool wallClosed, double contactGap,
                          double lateralHalfWidth) {
  LumenSection out;
  const std::vector<Segment> t = segmentsOf(tongue, tongueClosed), w = segmentsOf(wall, wallClosed);
  if (t.empty() || w.empty()) return out;
  const auto [tLo, tHi] = rangeOf(t);
  const auto [wLo, wHi] = rangeOf(w);
  out.uLeft = std::max({tLo, wLo, -lateralHalfWidth});
  out.uRight = std::min({tHi, wHi, lateralHalfWidth});
  if (!out.spansWidth()) return out;
  std::vector<double> breaks{out.uLeft, out.uRight};
  for (const auto *segs : {&t, &w}) {
    for (const auto &s : *segs)
      for (double u : {s.a.x(), s.b.x()}) breaks.push_back(u);
    addCrossings(*segs, breaks);
  }
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::remove_if(breaks.begin(), breaks.end(),
                              [&](double u) { return u < out.uLeft || u > out.uRight; }),
               breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  std::vector<Eigen::Vector2d> upper, lower;  // the outline's wall and tongue sides
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double a = breaks[k], b = breaks[k + 1], mid = 0.5 * (a + b);
    const Segment *st = envelopeAt(t, mid, true), *sw = envelopeAt(w, mid, false);
    if (!st || !sw) continue;  // a gap in a curve's lateral cover (not met on a connected curve)
    const double ta = st->at(a), tb = st->at(b), wa = sw->at(a), wb = sw->at(b);
    out.area += positivePart(wa - ta, wb - tb, b - a);
    const double touching = widthBelow(wa - ta, wb - tb, b - a, contactGap);
    out.contactWidth += touching;
    if (touching < b - a) out.openWidth += (b - a) - touching;
    out.largestGap = std::max({out.largestGap, wa - ta, wb - tb});
    if (lower.empty() || lower.back() != Eigen::Vector2d(a, ta)) lower.emplace_back(a, ta);
    lower.emplace_back(b, tb);
    if (upper.empty() || upper.back() != Eigen::Vector2d(a, wa)) upper.emplace_back(a, wa);
    upper.emplace_back(b, wb);
  }
  out.outline = lower;
  out.outline.insert(out.outline.end(), upper.rbegin(), upper.rend());
  return out;
}

}  // namespace glossa::airway
