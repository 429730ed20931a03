#pragma once
// How much of a trilinear hexahedron is turned inside out: the volume where det(dx/dxi) < 0,
//   V-(x) = int_{[-1,1]^3} max(0, -det dx/dxi) dxi,
// the part of the element that the volume integrals count negatively (material folded over
// itself). det dx/dxi of a trilinear map is a polynomial of degree 2 in each of xi, eta, zeta, so
// on any sub-box its 27 Bernstein coefficients bound it: a sub-box whose coefficients are all
// positive holds no turned-over volume, one whose coefficients are all negative is turned over
// whole (its integral is exact), and only those in between are split into eight sub-hexahedra.
//
// The fold measure judges an element against its own reference: the turned-over volume gained
// since the reference configuration (a zero-strain configuration may already have a turned-over
// sliver at a near-degenerate corner), as a fraction of the element's reference volume. A corner
// det F cannot tell a fold from a poor corner: a corner whose reference det dX/dxi is 0.03 of its
// element's mean turns det F there to -8 when it moves a fraction of the element's size, while
// only a sliver of the element is turned over (doc/theory.md, "Folded elements"). Eigen only.

#include "fem/HexShape.hpp"

namespace glossa::fem {

// V-(x) [m^3] for the element with nodal positions x; exact where the Bernstein bounds decide,
// otherwise to the Simpson rule on sub-hexahedra of 1/8 of the element's edge.
double turnedOverVolume(const NodeMatrix &x);
// int det dX/dxi dxi, the element's signed volume (exact: 2x2x2 Gauss points).
double hexVolume(const NodeMatrix &X);
// (V-(X + u) - V-(X)) / V(X), not below 0: the fraction of the element turned over since its
// reference configuration X. 0 for a reference of non-positive volume.
double turnedOverFraction(const NodeMatrix &X, const NodeMatrix &u);

// A converged state with an element turned over by more than this fraction is refused as folded.
// Measured (doc/theory.md, "Folded elements"): sound tongue runs keep at most 0.14 % (s8_4_sg,
// at a near-degenerate corner of the imaged mesh); a unit cube with a corner node pushed to its
// centre, the textbook fold, has 0.31 %; s8_4_ggm with every group fully active reaches 0.51 %
// and the step-44 block under ten times its load 0.79 %.
inline constexpr double kFoldedFraction = 0.0025;
inline bool folded(const NodeMatrix &X, const NodeMatrix &u) { return turnedOverFraction(X, u) > kFoldedFraction; }

} // namespace glossa::fem
