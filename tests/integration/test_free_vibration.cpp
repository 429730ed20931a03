// Free vibration by generalized-alpha (Time/analysis = dynamic) against independent references.
// The bar of inputs/verification/axial_vibration.xml (uniaxial strain, fixed-free, started in its
// first mode): its period against
// - the continuum's T = 4 L / c, c = sqrt((kappa + 4 mu / 3) / rho), to 1 %;
// - the semi-discrete bar's: linear elements of size h carry the mode sin(k X), k = pi / 2L,
//   exactly, at omega_h^2 = (6 c^2 / h^2)(1 - cos kh)/(2 + cos kh) with the consistent mass and
//   (2 c^2 / h^2)(1 - cos kh) with the lumped one;
// - times the trapezoidal rule's period elongation Omega / (2 atan(Omega / 2)), Omega = omega_h dt
//   (rho_inf = 1), so the measured period error against dt has slope 2 on a log-log scale.
// The large-amplitude cantilever of inputs/verification/nonlinear_vibration.xml (tip swing a quarter
// of its length): rho_inf = 1 keeps the total energy to 1e-3 over two periods here and ten in
// bench/free_vibration.py (the trapezoidal
// rule's error is second order in dt: 2.3e-3, 3.0e-4, 7.5e-5 over 2.5 periods at 60, 120, 240
// steps a period); rho_inf = 0.5 removes the high modes' energy and keeps the first mode's.
// The same cantilever nearly incompressible (nu = 0.49999, augmented Lagrangian): the dilatation
// error below 0.1 % after every step, and with rho_inf = 0.5 the element pressure's history as
// smooth at dt as at dt/2 (its total variation the same to 5 %), where rho_inf = 1 oscillates.
// Backward Euler on the bar: its energy loss and period elongation as its closed form says.
// The energy-conserving step on the cantilever: the energy to Newton's tolerance at nu = 0.3, and
// to 1e-3 at nu = 0.49999, where the trapezoidal rule gains energy.

#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "LastStepField.hpp"
#include "RunDeck.hpp"

namespace glossa::test {
namespace {

constexpr double kLength = 0.1, kCells = 20, kMu = 1000.0, kNu = 0.3, kRho = 1000.0;

double waveSpeed() {
  const double kappa = 2.0 * kMu * (1.0 + kNu) / (3.0 * (1.0 - 2.0 * kNu));
  return std::sqrt((kappa + 4.0 * kMu / 3.0) / kRho);
}
double continuumPeriod() { return 4.0 * kLength / waveSpeed(); }
// The semi-discrete bar's first period.
double discretePeriod(bool lumped) {
  const double h = kLength / kCells, c = waveSpeed(), kh = M_PI / (2.0 * kLength) * h;
  const double omega2 = lumped ? 2.0 * c * c / (h * h) * (1.0 - std::cos(kh))
                               : 6.0 * c * c / (h * h) * (1.0 - std::cos(kh)) / (2.0 + std::cos(kh));
  return 2.0 * M_PI / std::sqrt(omega2);
}
// The trapezoidal rule's period for a mode of period T at step dt.
double trapezoidalPeriod(double T, double dt) {
  const double Omega = 2.0 * M_PI / T * dt;
  return T * Omega / (2.0 * std::atan(0.5 * Omega));
}

// The mean time between the upward zero crossings of the tip's u_x (linear interpolation
// between steps: at a crossing of a sine its curvature vanishes, so the error is O(dt^3)).
double measuredPeriod(const std::filesystem::path &traces) {
  const auto ux = traceOf(readTraces(traces), "tip", 0);
  std::vector<double> up;
  double tPrev = 0.0, uPrev = 0.0;
  bool first = true;
  for (const auto &[t, u] : ux) {
    if (!first && uPrev < 0.0 && u >= 0.0) up.push_back(tPrev + (t - tPrev) * (-uPrev) / (u - uPrev));
    tPrev = t;
    uPrev = u;
    first = false;
  }
  // The bar starts at u = 0 moving up: t = 0 is the first upward crossing.
  EXPECT_GE(up.size(), 1u);
  return up.empty() ? 0.0 : up.back() / static_cast<double>(up.size());
}

double runBar(const std::string &name, double dt, bool lumped, double periods) {
  const auto dir = scratchDirectory("free_vibration_" + name);
  std::vector<std::string> sets{"Time/step size=" + std::to_string(dt),
                                "Time/end time=" + std::to_string(periods * continuumPeriod()),
                                "Output/fields=false"};
  if (lumped) sets.push_back("Time/mass matrix=lumped");
  const auto summary = runDeck(inputPath("verification/axial_vibration.xml"), sets, dir);
  EXPECT_TRUE(summary.at("converged").get<bool>()) << name;
  return measuredPeriod(dir / "traces.csv");
}

TEST(FreeVibration, AxialPeriodIsTheAnalyticOneAndTheTrapezoidalRulesElongation) {
  for (bool lumped : {false, true}) {
    const double dt = continuumPeriod() / 40.0;
    const double T = runBar(lumped ? "lumped" : "consistent", dt, lumped, 2.1);
    EXPECT_NEAR(T / continuumPeriod(), 1.0, 0.01) << (lumped ? "lumped" : "consistent");
    const double predicted = trapezoidalPeriod(discretePeriod(lumped), dt);
    EXPECT_NEAR(T / predicted, 1.0, 1e-4) << (lumped ? "lumped" : "consistent");
    std::printf("%s mass: T = %.6f s, continuum %.6f s, semi-discrete %.6f s, with the step %.6f s\n",
                lumped ? "lumped" : "consistent", T, continuumPeriod(), discretePeriod(lumped), predicted);
  }
}

TEST(FreeVibration, PeriodErrorIsSecondOrderInTheStep) {
  const double Th = discretePeriod(false);
  std::vector<double> errors;
  for (int steps : {20, 40, 80}) {
    const double T = runBar("order_" + std::to_string(steps), continuumPeriod() / steps, false, 1.1);
    errors.push_back(T / Th - 1.0);
    std::printf("%d steps a period: period error %.4e\n", steps, errors.back());
  }
  for (std::size_t i = 0; i + 1 < errors.size(); ++i) {
    ASSERT_GT(errors[i + 1], 0.0);
    EXPECT_NEAR(std::log(errors[i] / errors[i + 1]) / std::log(2.0), 2.0, 0.05);
  }
}

// energy.csv's total energy per step, by time.
std::map<double, double> totalEnergy(const std::filesystem::path &dir) {
  std::map<double, double> total;
  const auto rows = readKeyedCsv(dir / "energy.csv");
  for (const auto &row : rows.at("all")) total[row.time] = row.values.at(2);
  return total;
}
// The energy at the row nearest time t.
double energyAt(const std::map<double, double> &E, double t) {
  auto at = E.lower_bound(t);
  if (at == E.end()) --at;
  return at->second;
}

TEST(FreeVibration, TrapezoidalRuleKeepsTheEnergyOfALargeNonlinearVibration) {
  const auto dir = scratchDirectory("free_vibration_energy");
  // Two of the deck's 10 periods here (bench/free_vibration.py runs all 10: largest change 3.9e-4).
  const auto summary = runDeck(inputPath("verification/nonlinear_vibration.xml"),
                               {"Output/fields=false", "Time/end time=1.2"}, dir);
  ASSERT_TRUE(summary.at("converged").get<bool>());
  const auto E = totalEnergy(dir);
  ASSERT_EQ(E.size(), 241u); // two periods of about 0.6 s, 120 steps each
  const double E0 = E.begin()->second;
  double worst = 0.0;
  for (const auto &[t, e] : E) worst = std::max(worst, std::abs(e / E0 - 1.0));
  std::printf("rho_inf = 1: %zu steps, largest relative change of the total energy %.3e\n", E.size(), worst);
  EXPECT_LT(worst, 1e-3); // so no growth either
}

TEST(FreeVibration, SpectralRadiusBelowOneDampsTheHighModesAndKeepsTheLowOne) {
  // The initial velocity (X/L)^2 is mostly the first bending mode with some of the higher ones.
  // rho_inf = 0.5 takes out those the step does not resolve within a few steps, then the first
  // mode, 120 steps a period, keeps its energy (its damping is of order (w dt)^3).
  const auto dir = scratchDirectory("free_vibration_dissipative");
  const auto summary = runDeck(inputPath("verification/nonlinear_vibration.xml"),
                               {"Output/fields=false", "Time/spectral radius=0.5", "Time/end time=1.2"}, dir);
  ASSERT_TRUE(summary.at("converged").get<bool>());
  const auto E = totalEnergy(dir);
  const double E0 = E.begin()->second, E1 = energyAt(E, 0.6), E2 = energyAt(E, 1.2);
  std::printf("rho_inf = 0.5: total energy %.6e J at t = 0, %.6e after a period, %.6e after two\n", E0, E1, E2);
  for (const auto &[t, e] : E) EXPECT_LE(e, E0) << "t = " << t;
  EXPECT_LT(E1 / E0 - 1.0, -1e-3);                   // more than rho_inf = 1's largest change
  EXPECT_NEAR(E2 / E1, 1.0, 1e-3);                   // the low mode keeps its energy
}

// The energy-conserving step (Time/integrator = energy conserving): each element's force a
// discrete gradient of its stored energy, so the kinetic plus stored energy is conserved to the
// solver's tolerance, not to the trapezoidal rule's O(dt^2) (2.3e-3 at these 60 steps a period).
TEST(FreeVibration, EnergyConservingStepKeepsTheEnergyToTheSolversTolerance) {
  const auto dir = scratchDirectory("free_vibration_energy_conserving");
  const auto summary = runDeck(inputPath("verification/nonlinear_vibration.xml"),
                               {"Output/fields=false", "Time/end time=1.2", "Time/step size=0.01",
                                "Time/integrator=energy conserving"},
                               dir);
  ASSERT_TRUE(summary.at("converged").get<bool>());
  const auto E = totalEnergy(dir);
  ASSERT_EQ(E.size(), 121u);
  const double E0 = E.begin()->second;
  double worst = 0.0;
  for (const auto &[t, e] : E) worst = std::max(worst, std::abs(e / E0 - 1.0));
  std::printf("energy-conserving step, nu = 0.3: largest relative change of the total energy %.3e\n", worst);
  EXPECT_LT(worst, 1e-6); // measured 1.7e-8, Newton's tolerance
}

// The nearly incompressible cantilever (nu = 0.49999, augmented Lagrangian): the trapezoidal rule
// gains energy from the second period on (the volumetric modes it leaves undamped take it up
// through the nonlinear force; the run stops at 1.7 s), the energy-conserving step keeps it to
// 1e-3 (measured 3e-5 over ten periods in bench/free_vibration.py), with the dilatation error
// below the deck's 1e-6 after every step.
TEST(FreeVibration, NearlyIncompressibleEnergyConservingStepKeepsTheEnergyTheTrapezoidalRuleGains) {
  const std::string deck = inputPath("verification/nonlinear_vibration_nearly_incompressible.xml");
  std::map<std::string, double> largestRise;
  for (const auto &[name, integrator] : std::vector<std::pair<std::string, std::string>>{
           {"energy_conserving", "Time/integrator=energy conserving"},
           {"trapezoidal", "Time/integrator=generalized-alpha"}}) {
    const auto dir = scratchDirectory("free_vibration_incompressible_" + name);
    const auto summary = runDeck(deck, {"Output/fields=false", "Time/end time=1.2", integrator}, dir);
    ASSERT_TRUE(summary.at("converged").get<bool>()) << name;
    for (const auto &step : summary.at("steps"))
      EXPECT_LE(step.at("max_dilatation_error").get<double>(), 1e-6) << name << " t = " << step.at("time");
    const auto E = totalEnergy(dir);
    const double E0 = E.begin()->second;
    double worst = 0.0, rise = 0.0;
    for (const auto &[t, e] : E) {
      worst = std::max(worst, std::abs(e / E0 - 1.0));
      rise = std::max(rise, e / E0 - 1.0);
    }
    largestRise[name] = rise;
    std::printf("nu = 0.49999, %s: %zu steps, largest relative change of the total energy %.3e, largest rise %.3e\n",
                name.c_str(), E.size(), worst, rise);
    if (name == "energy_conserving") {
      EXPECT_LT(worst, 1e-3);
    }
  }
  EXPECT_GT(largestRise["trapezoidal"], 1e-2); // measured 2.5e-2 by 1.2 s
  EXPECT_LT(largestRise["energy_conserving"], 1e-4);
}

// The element pressures of every written step (every step: Output/every = 1), step by step.
std::vector<std::vector<double>> pressureHistory(const std::filesystem::path &dir) {
  std::vector<std::vector<double>> p;
  for (const auto &file : stepFiles(dir)) {
    const io::testing::Hdf5File h5(file);
    p.push_back(h5.doubles("/" + file.stem().string() + "/pressure").values);
  }
  return p;
}
std::vector<double> ofElement(const std::vector<std::vector<double>> &history, std::size_t e) {
  std::vector<double> p;
  for (const auto &step : history) p.push_back(step.at(e));
  return p;
}
double totalVariation(const std::vector<double> &p) {
  double tv = 0.0;
  for (std::size_t n = 0; n + 1 < p.size(); ++n) tv += std::abs(p[n + 1] - p[n]);
  return tv;
}

TEST(FreeVibration, NearlyIncompressiblePressureStaysSmoothWhenTheVolumetricModesAreDamped) {
  const std::vector<std::string> common{"Material/Poisson's ratio=0.49999", "Incompressibility/method=augmented Lagrangian",
                                        "Incompressibility/dilatation tolerance=1e-6", "Time/end time=0.6",
                                        "Output/every=1"};
  std::map<std::string, std::filesystem::path> dirs;
  for (const auto &[name, sets] : std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"rho05_dt", {"Time/spectral radius=0.5", "Time/step size=0.005"}},
           {"rho05_half", {"Time/spectral radius=0.5", "Time/step size=0.0025"}},
           {"rho1_dt", {"Time/spectral radius=1", "Time/step size=0.005"}}}) {
    std::vector<std::string> all = common;
    all.insert(all.end(), sets.begin(), sets.end());
    dirs[name] = scratchDirectory("free_vibration_incompressible_" + name);
    const auto summary = runDeck(inputPath("verification/nonlinear_vibration.xml"), all, dirs[name]);
    ASSERT_TRUE(summary.at("converged").get<bool>()) << name;
    for (const auto &step : summary.at("steps"))
      EXPECT_LE(step.at("max_dilatation_error").get<double>(), 1e-3) << name << " t = " << step.at("time");
  }
  // The element whose pressure swings furthest in the converged reference (dt/2).
  const auto reference = pressureHistory(dirs["rho05_half"]);
  std::size_t e = 0;
  double largest = 0.0;
  for (std::size_t i = 0; i < reference.front().size(); ++i)
    if (maxAbs(ofElement(reference, i)) > largest) {
      largest = maxAbs(ofElement(reference, i));
      e = i;
    }
  const double converged = totalVariation(ofElement(reference, e));
  const double damped = totalVariation(ofElement(pressureHistory(dirs["rho05_dt"]), e));
  const double trapezoidal = totalVariation(ofElement(pressureHistory(dirs["rho1_dt"]), e));
  std::printf("element %zu: pressure total variation %.1f Pa (rho_inf 0.5, dt/2), %.1f (0.5, dt), %.1f (1, dt)\n", e,
              converged, damped, trapezoidal);
  EXPECT_NEAR(damped / converged, 1.0, 0.05);
  EXPECT_GT(trapezoidal / converged, 1.2); // the undamped volumetric modes' step-to-step oscillation
}

// Backward Euler (Time/integrator) on the bar: one step multiplies its mode by 1/(1 - i Omega_h),
// Omega_h = omega_h dt, so the energy falls by exactly 1/(1 + Omega_h^2) a step and the period is
// the semi-discrete one times Omega_h / atan(Omega_h); the energy lost a period halves with the step
// (first order), where generalized-alpha's is of third order.
// The bar's deck without its spectral radius, which backward Euler does not read (and so refuses).
std::string barDeckWithoutSpectralRadius() {
  std::ifstream in(inputPath("verification/axial_vibration.xml"));
  const auto dir = scratchDirectory("free_vibration_backward_euler_deck");
  std::filesystem::create_directories(dir);
  const auto path = dir / "axial_vibration.xml";
  std::ofstream out(path);
  for (std::string line; std::getline(in, line);)
    if (line.find("\"spectral radius\"") == std::string::npos) out << line << "\n";
  return path.string();
}

TEST(FreeVibration, BackwardEulerDissipatesAsItsClosedFormAtFirstOrder) {
  const double Th = discretePeriod(false);
  std::vector<double> lossPerPeriod;
  for (int steps : {40, 80}) {
    const double dt = continuumPeriod() / steps, Omega = 2.0 * M_PI / Th * dt;
    const auto dir = scratchDirectory("free_vibration_backward_euler_" + std::to_string(steps));
    const auto summary = runDeck(barDeckWithoutSpectralRadius(),
                                 {"Time/step size=" + std::to_string(dt), "Time/end time=" + std::to_string(1.1 * continuumPeriod()),
                                  "Output/fields=false", "Time/integrator=backward Euler"},
                                 dir);
    ASSERT_TRUE(summary.at("converged").get<bool>()) << steps;
    const double T = measuredPeriod(dir / "traces.csv");
    const auto E = totalEnergy(dir);
    // Each step, whatever its size (the last one ends on the end time), multiplies the energy by
    // 1/(1 + (omega_h dt_k)^2).
    double predicted = 1.0, tPrev = 0.0;
    for (const auto &[t, e] : E) {
      const double Ok = 2.0 * M_PI / Th * (t - tPrev);
      predicted /= 1.0 + Ok * Ok;
      tPrev = t;
    }
    const double ratio = E.rbegin()->second / E.begin()->second;
    std::printf("backward Euler, %d steps a period: T = %.6f s (predicted %.6f), energy ratio %.5f after %zu steps "
                "(predicted %.5f)\n", steps, T, Th * Omega / std::atan(Omega), ratio, E.size() - 1, predicted);
    EXPECT_NEAR(T / (Th * Omega / std::atan(Omega)), 1.0, 1e-3) << steps;
    EXPECT_NEAR(std::log(ratio) / std::log(predicted), 1.0, 2e-3) << steps;
    lossPerPeriod.push_back(-std::log(ratio) / tPrev * Th);
  }
  EXPECT_NEAR(std::log(lossPerPeriod[0] / lossPerPeriod[1]) / std::log(2.0), 1.0, 0.02);
}

} // namespace
} // namespace glossa::test
