#include "airway/AirwayLumen.hpp"

#include <utility>

#include "airway/PlaneCut.hpp"

namespace glossa::airway {

namespace {
std::vector<Eigen::Vector2d> inPlane(const CutCurve &c, const SectionPlane &p) {
  std::vector<Eigen::Vector2d> uv;
  for (const auto &x : c.points) uv.push_back(p.inPlane(x));
  return uv;
}
}  // namespace

bool sectionCloses(const LumenSection &lumen, const LumenSettings &settings) {
  return lumen.area < settings.closingArea || lumen.touchesOver(settings.closingWidthFraction);
}

AirwayLumen::AirwayLumen(TriangleSet tongue, TriangleSet wall, const CentrelineSettings &centreline,
                         LumenSettings settings)
    : tongue_(std::move(tongue)), wall_(std::move(wall)),
      centreline_(buildCentreline(tongue_, wall_, centreline)), settings_(settings) {}

LumenState AirwayLumen::measure(const std::vector<Eigen::Vector3d> &positions) const {
  LumenState state;
  for (const SectionPlane &plane : centreline_.planes) {
    SectionState section;
    const std::vector<CutCurve> tongueCuts = cutSurface(positions, tongue_.triangles, plane);
    const std::vector<CutCurve> wallCuts = cutSurface(wall_.vertices, wall_.triangles, plane);
    const CutCurve *t = nearestCurve(tongueCuts, plane.origin), *w = nearestCurve(wallCuts, plane.origin);
    if (t && w) {
      section.lumen = lumenBetween(inPlane(*t, plane), t->closed, inPlane(*w, plane), w->closed, settings_.contactGap,
                                   settings_.lateralHalfWidth);
      section.measured = section.lumen.spansWidth();
    }
    section.closed = section.measured && sectionCloses(section.lumen, settings_);
    if (section.closed) ++state.closedSections;
    const int k = static_cast<int>(state.sections.size());
    if (section.measured &&
        (state.smallest < 0 || section.lumen.area < state.sections[static_cast<std::size_t>(state.smallest)].lumen.area))
      state.smallest = k;
    state.sections.push_back(std::move(section));
  }
  return state;
}

}  // namespace glossa::airway
