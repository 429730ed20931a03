#pragma once
// The lumen's area in one section plane, between two curves written in the plane's (u, v)
// coordinates: the tongue's, below (smaller v), and the wall's, above. Each curve is read as a
// function of the lateral coordinate u, v_t(u) the upper envelope of the tongue's segments (the
// side facing the wall) and v_w(u) the lower envelope of the wall's; the sides are closed by
// lines of constant u at the lateral limits both curves span, [u_left, u_right] = [max of the
// two curves' smallest u, min of their largest u], or at the lateral walls u = -h and u = h where
// those are narrower (h = lateralHalfWidth, u = 0 on the midsagittal plane). The area is
//
//   A = \int_{u_left}^{u_right} max(0, v_w(u) - v_t(u)) du,
//
// exact for the piecewise linear curves (the envelopes' breakpoints and the gap's zero crossings
// are found, and each piece integrated in closed form), so a section through a faceted channel
// gives the faceted channel's area to round-off. Where the tongue lies on or past the wall the
// gap counts as zero (contact, or a penetration within the contact's tolerance).

#include <Eigen/Core>
#include <limits>
#include <vector>

namespace glossa::airway {

struct LumenSection {
  double area = 0.0;                       // [m^2]
  double uLeft = 0.0, uRight = 0.0;        // the common lateral range [m]
  double contactWidth = 0.0;               // the width where the gap is <= the contact gap [m]
  double openWidth = 0.0;                  // the rest, where the gap is larger [m]
  double largestGap = 0.0;                 // [m]
  // The lumen's outline, (u, v): the tongue's envelope left to right, then the wall's right to
  // left (the closing sides are the jumps between them).
  std::vector<Eigen::Vector2d> outline;
  bool spansWidth() const { return uRight > uLeft; }
  // The fraction of the width in contact.
  double contactFraction() const { return spansWidth() ? contactWidth / (uRight - uLeft) : 0.0; }
  // Touching from side to side: no open width at all (exactly 0, not a sum compared with the
  // width, which round-off would miss).
  bool touchesAcross() const { return spansWidth() && openWidth == 0.0; }
  // Touching over at least `fraction` (in (0, 1]) of the width; 1 is touchesAcross, exactly.
  bool touchesOver(double fraction) const {
    return fraction >= 1.0 ? touchesAcross() : spansWidth() && contactWidth >= fraction * (uRight - uLeft);
  }
};

// The lumen between the tongue's curve and the wall's (each a polyline of (u, v) points, in
// order; `closed` joins the last point to the first). `contactGap`: a gap at or below it counts
// as contact for contactWidth. `lateralHalfWidth` (> 0): the lateral walls at u = +-h bound the
// width too. Curves whose lateral ranges do not overlap (within the walls) give area 0 and an
// empty outline.
LumenSection lumenBetween(const std::vector<Eigen::Vector2d> &tongue, bool tongueClosed,
                          const std::vector<Eigen::Vector2d> &wall, bool wallClosed, double contactGap,
                          double lateralHalfWidth = std::numeric_limits<double>::infinity());

}  // namespace glossa::airway
