#pragma once
// The airway's lumen between the tongue's airway surface and a rigid wall (the palate and the
// posterior pharyngeal wall), measured in fixed cross-section planes (airway/Centreline) from the
// tongue's current shape: in each plane, the curve of the tongue's surface and that of the wall
// nearest the section's centre (airway/PlaneCut), and the area between them with the sides
// closed at the lateral limits both span (airway/LumenArea). The tongue's quadrilateral faces are
// cut as two triangles each (split along the diagonal from their first corner), the same surface
// at rest and deformed. A section is closed when its area is below the closing area or the gap is
// at most the contact gap over the closing width fraction of its width (by default the whole
// width; less lets a model without lateral walls close although its sides stay open). Lateral
// walls, when given, are planes at a fixed distance either side of the midsagittal plane that
// bound the width; the tongue does not touch them (a measuring bound, not an obstacle).

#include <Eigen/Core>
#include <array>
#include <limits>
#include <vector>

#include "airway/Centreline.hpp"
#include "airway/LumenArea.hpp"

namespace glossa::airway {

struct LumenSettings {
  double closingArea = 1e-6;  // [m^2]
  double contactGap = 1e-5;   // [m]
  double closingWidthFraction = 1.0;  // in (0, 1]
  // The lateral walls, planes parallel to the midsagittal one at this distance on either side:
  // they bound every section's width (infinity: no walls, the narrower surface's edges do).
  double lateralHalfWidth = std::numeric_limits<double>::infinity();  // [m], > 0
};

// Whether a measured section is closed under `settings`.
bool sectionCloses(const LumenSection &lumen, const LumenSettings &settings);

struct SectionState {
  bool measured = false;  // both surfaces cut the plane near its centre, over a common width
  LumenSection lumen;
  bool closed = false;
  double area() const { return measured ? lumen.area : std::numeric_limits<double>::quiet_NaN(); }
};

struct LumenState {
  std::vector<SectionState> sections;
  int smallest = -1;  // the section of least area among those measured; -1 if none is
  int closedSections = 0;
  bool closed() const { return closedSections > 0; }
};

class AirwayLumen {
 public:
  // `tongue`: the airway faces as triangles of their own vertex list (its positions at rest);
  // `wall`: the rigid wall; the centreline is built from both at rest.
  AirwayLumen(TriangleSet tongue, TriangleSet wall, const CentrelineSettings &centreline, LumenSettings settings);

  // The lumen with the tongue's vertices at `positions` (in the order of the tongue's vertices).
  LumenState measure(const std::vector<Eigen::Vector3d> &positions) const;

  const Centreline &centreline() const { return centreline_; }
  const LumenSettings &settings() const { return settings_; }
  std::size_t numSections() const { return centreline_.planes.size(); }

 private:
  TriangleSet tongue_, wall_;
  Centreline centreline_;
  LumenSettings settings_;
};

}  // namespace glossa::airway
