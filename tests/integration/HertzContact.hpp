#pragma once
// Hertz's cylinder on a rigid plane (doc/contact.md, "Hertz"), shared by the CI test and the
// finer study in bench/: the closed form from a deck's parameters and the measured load, and the
// contact half-width and peak pressure measured on a run's contact_pressure node field.
//
// The half-width a is where the pressure profile along the surface falls to zero. Near any smooth
// contact edge p grows as sqrt(a - x), so p^2 is linear in x there: a is the zero of the line
// through p^2 at the last two loaded nodes (ordered by their deformed x), kept between the last
// loaded node and the first unloaded one. This uses the profile's local shape at its edge only,
// not Hertz's ellipse.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "Hdf5Reading.hpp"
#include "LastStepField.hpp"
#include "RunDeck.hpp"

namespace glossa::test {

struct HertzReference {
  double a;  // contact half-width [m]
  double p0; // peak pressure [Pa]
};

// A cylinder of radius R pressed by P per unit length on a rigid plane, E* = E / (1 - nu^2) =
// 2 mu / (1 - nu) (E = 2 mu (1 + nu)).
inline HertzReference hertzCylinder(double loadPerLength, double radius, double shearModulus, double poisson) {
  const double eStar = 2.0 * shearModulus / (1.0 - poisson);
  const double a = std::sqrt(4.0 * loadPerLength * radius / (M_PI * eStar));
  return {a, 2.0 * loadPerLength / (M_PI * a)};
}

// The contact nodes of the layer z = 0 (those with a finite contact_gap), by deformed x.
struct PressureProfile {
  std::vector<double> x, p;
};

inline PressureProfile lastPressureProfile(const std::filesystem::path &run) {
  const io::testing::Hdf5File mesh(run / "results.h5");
  const auto X = mesh.doubles("/mesh/coordinates").values;
  const auto u = lastStepField(run, "displacement"), p = lastStepField(run, "contact_pressure"),
             gap = lastStepField(run, "contact_gap");
  std::vector<std::pair<double, double>> points;
  for (std::size_t n = 0; n < p.size(); ++n)
    if (X[3 * n + 2] == 0.0 && std::isfinite(gap[n])) points.emplace_back(X[3 * n] + u[3 * n], p[n]);
  std::sort(points.begin(), points.end());
  PressureProfile out;
  for (const auto &[x, pressure] : points) {
    out.x.push_back(x);
    out.p.push_back(pressure);
  }
  return out;
}

struct HertzMeasure {
  double a;           // half-width where the profile falls to zero [m]
  double p0;          // pressure at the lowest node, x = 0 [Pa]
  double deviation;   // max |p - Hertz's ellipse| / Hertz's p0 over the nodes inside 0.8 a_Hertz
  double oscillation; // max |second difference of (p - ellipse)| / Hertz's p0 there: the zig-zag
  int loadedNodes;    // nodes carrying pressure
};

// Smoothness is measured inside 0.8 a_Hertz: nearer the edge the profile's slope grows without
// bound and any discretisation errs most, whatever its contact points.
inline HertzMeasure measureHertz(const PressureProfile &profile, const HertzReference &hertz) {
  const auto &x = profile.x, &p = profile.p;
  std::size_t last = 0;
  int loaded = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p[i] > 0.0) {
      last = i;
      ++loaded;
    }
  if (loaded < 2 || last + 1 >= x.size()) throw std::runtime_error("measureHertz: no contact edge in the profile");
  const double rise = p[last - 1] * p[last - 1] - p[last] * p[last];
  double a = x[last + 1];
  if (rise > 0.0) a = std::min(a, x[last] + p[last] * p[last] * (x[last] - x[last - 1]) / rise);
  std::vector<double> d(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double s = x[i] / hertz.a;
    d[i] = (p[i] - (s < 1.0 ? hertz.p0 * std::sqrt(1.0 - s * s) : 0.0)) / hertz.p0;
  }
  double deviation = 0.0, oscillation = 0.0;
  for (std::size_t i = 0; i < p.size() && x[i] < 0.8 * hertz.a; ++i) {
    deviation = std::max(deviation, std::abs(d[i]));
    if (i > 0 && i + 1 < p.size() && x[i + 1] < 0.8 * hertz.a)
      oscillation = std::max(oscillation, std::abs(d[i] - 0.5 * (d[i - 1] + d[i + 1])));
  }
  return {a, p[0], deviation, oscillation, loaded};
}

// The last row's normal force [N] of one contact in contact.csv.
inline double lastNormalForce(const std::filesystem::path &run, const std::string &contact) {
  std::ifstream in(run / "contact.csv");
  std::string line, cell, key;
  double force = NAN;
  std::getline(in, line); // header
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::getline(s, cell, ',');
    std::getline(s, key, ',');
    std::getline(s, cell, ','); // area
    std::getline(s, cell, ',');
    if (key == contact) force = std::stod(cell);
  }
  return force;
}

// One run of a hertz_*.xml deck with its mesh counts (all but the axial one) times `scale` and
// the given contact points, measured against Hertz at the load it reached.
struct HertzRun {
  HertzReference hertz;
  HertzMeasure measured;
  double radius, eStar;
  int elements, newton, uzawa, contactUpdates;
  double seconds, maxDilatationError;
  bool gapToleranceMet;
  double errorA() const { return measured.a / hertz.a - 1.0; }
  double errorP0() const { return measured.p0 / hertz.p0 - 1.0; }
};

inline HertzRun runHertz(const std::string &deckFile, double scale, const std::string &rule,
                         const std::filesystem::path &output, std::vector<std::string> overrides = {}) {
  const auto schema = app::deckSchema();
  auto deck = io::Deck::fromFile(deckFile);
  deck.validate(schema);
  const auto &cylinder = deck.root().sublist("Mesh").sublist("Quarter cylinder");
  const auto &material = deck.root().sublist("Material");
  const double radius = cylinder.get<double>("radius"), height = cylinder.get<double>("height");
  const double mu = material.get<double>("shear modulus"), nu = material.get<double>("Poisson's ratio");
  auto cells = cylinder.get<Teuchos::Array<int>>("cells");
  std::string counts;
  for (int i = 0; i < 4; ++i) {
    const double n = cells[i] * scale;
    if (n != std::round(n) || n < 1) throw std::runtime_error("runHertz: cells x scale must be whole");
    cells[i] = static_cast<int>(n);
  }
  for (int n : cells) counts += (counts.empty() ? "" : ",") + std::to_string(n);
  overrides.push_back("Mesh/Quarter cylinder/cells={" + counts + "}");
  overrides.push_back("Contact/plane/contact points=" + rule);
  const auto summary = runDeck(deckFile, overrides, output);
  if (!summary.at("converged").get<bool>()) throw std::runtime_error(deckFile + ": the run did not converge");
  // The model is half the cylinder: the plane's force on it is half the load of the whole.
  const double load = 2.0 * lastNormalForce(output, "plane") / height;
  HertzRun r{hertzCylinder(load, radius, mu, nu), {}, radius, 2.0 * mu / (1.0 - nu), 0, 0, 0, 0, 0.0, 0.0, false};
  r.measured = measureHertz(lastPressureProfile(output), r.hertz);
  const int na = cells[0] + cells[1], nb = cells[2], nr = cells[3];
  r.elements = (na * nb + (na + nb) * nr) * cells[4];
  for (const auto &step : summary.at("steps")) {
    r.newton += step.at("newton_iterations").get<int>();
    r.uzawa += step.at("uzawa_iterations").get<int>();
    r.contactUpdates += step.at("contact_updates").get<int>();
    r.maxDilatationError = std::max(r.maxDilatationError, step.at("max_dilatation_error").get<double>());
  }
  r.gapToleranceMet = summary.at("contact").at("gap_tolerance_met").get<bool>();
  r.seconds = summary.at("wall_seconds").get<double>();
  return r;
}

} // namespace glossa::test
