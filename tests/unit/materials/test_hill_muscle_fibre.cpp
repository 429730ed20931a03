#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "materials/ActivationDynamics.hpp"
#include "materials/HillMuscleFibre.hpp"

using namespace glossa::materials;

namespace {
constexpr double kT0max = 668.8e3;

HillMuscleFibre fibre(double T0s, const ContractileCurves &curves) {
  return HillMuscleFibre::tableI(T0s, curves);
}

// Hill (shortening) and van Soest-Bobbert (lengthening) targets of the physiological f_cV.
double hillAndVanSoest(double v) {
  return v <= 0.0 ? (1.0 + v / 10.0) / (1.0 - v / 2.5) : 1.5 - 0.25 / (v + 0.5);
}
constexpr double kForceVelocityFitResidual = 0.0605;  // doc/materials.md
}  // namespace

TEST(SeriesElement, TensionStiffnessAndEnergy) {
  const SeriesElement s = SeriesElement::tableI(kT0max);
  for (double lambdaC : {0.7, 1.0, 1.3})
    for (double lambdaS : {1.001, 1.01, 1.03}) {
      const double lambdaF = lambdaS * lambdaC, h = 1e-7;
      const SeriesTension t = s.evaluate(lambdaF, lambdaC);
      EXPECT_NEAR(t.T, kT0max * 0.1 * (std::exp(100 * (lambdaS - 1)) - 1), 1e-9 * kT0max);  // eq. 18
      EXPECT_NEAR(t.dLambdaF,
                  (s.evaluate(lambdaF + h, lambdaC).T - s.evaluate(lambdaF - h, lambdaC).T) / (2 * h),
                  1e-6 * t.dLambdaF);
      EXPECT_NEAR(t.dLambdaC,
                  (s.evaluate(lambdaF, lambdaC + h).T - s.evaluate(lambdaF, lambdaC - h).T) / (2 * h),
                  -1e-6 * t.dLambdaC);
      EXPECT_NEAR(
          t.T, (s.evaluate(lambdaF + h, lambdaC).energy - s.evaluate(lambdaF - h, lambdaC).energy) / (2 * h),
          1e-6 * t.T + 1e-3);
      EXPECT_NEAR(s.stretchAtTension(t.T), lambdaS, 1e-12);
    }
  EXPECT_EQ(s.evaluate(0.9, 1.0).T, 0.0);  // slack (tension only)
  EXPECT_EQ(s.evaluate(1.0, 1.0).T, 0.0);
}

// Zero activation (alpha = 0 or T0s = 0): the fibre is its parallel element, lambda_c = lambda_f.
TEST(HillMuscleFibre, ZeroActivationIsPassive) {
  const ParallelElement p = ParallelElement::tableI();
  for (const auto &f : {fibre(1.0, physiologicalCurves()), fibre(0.0, paperTableIICurves())})
    for (double lambdaF : {0.7, 1.0, 1.2})
      for (double alpha : {0.0, 0.4}) {
        if (alpha > 0 && f.contractile().T0s() > 0) continue;
        const HillFibreResponse r = f.evaluate({lambdaF, alpha, 0.01, 0.9});
        EXPECT_EQ(r.status, HillSolveStatus::Slack);
        EXPECT_EQ(r.lambdaC, lambdaF);
        EXPECT_EQ(r.T, p.evaluate(lambdaF).T);
        EXPECT_EQ(r.dTdLambdaF, p.evaluate(lambdaF).dTdLambda);
        EXPECT_EQ(r.Ts, 0.0);
      }
  // Stress-free reference: lambda_f = lambda_c = 1, no activation.
  EXPECT_EQ(fibre(1.0, physiologicalCurves()).evaluate({1.0, 0.0, 0.005, 1.0}).T, 0.0);
}

// The local solve converges (or reports slack consistently) over lambda_f in [0.5, 2], alpha and
// T0s in [0, 1], dt from 0.01 ms to 100 ms and lambda_c_old across the f_cL support.
TEST(HillMuscleFibre, LocalSolveConvergesAtTheCorners) {
  int taut = 0, slack = 0, onJump = 0;
  for (const ContractileCurves &curves : {paperTableIICurves(), physiologicalCurves()})
    for (double T0s : {0.0, 0.05, 1.0}) {
      const HillMuscleFibre f = fibre(T0s, curves);
      for (double lambdaF : {0.5, 0.7, 1.0, 1.3, 2.0})
        for (double alpha : {0.0, 1e-3, 0.5, 1.0})
          for (double dt : {1e-5, 1e-3, 0.1})
            for (double lambdaCOld : {0.5, 0.9, 1.0, 1.5, 2.0}) {
              const HillFibreResponse r = f.evaluate({lambdaF, alpha, dt, lambdaCOld});
              ASSERT_TRUE(succeeded(r.status)) << describe(r.status) << " lambda_f " << lambdaF << " alpha "
                                               << alpha << " dt " << dt << " lambda_c_old " << lambdaCOld;
              EXPECT_LE(r.iterations, 100);
              EXPECT_NEAR(r.lambdaCRate, (r.lambdaC - lambdaCOld) / dt,
                          1e-9 * std::abs(r.lambdaCRate) + 1e-12);
              const ContractileTension cAtFibre =
                  f.contractile().evaluate(lambdaF, (lambdaF - lambdaCOld) / dt, alpha);
              if (r.status == HillSolveStatus::Taut || r.status == HillSolveStatus::OnCurveJump) {
                ++taut;
                // Independently: T_s = T_c at the returned lambda_c (or within the jump of the curve
                // there), series not compressed, rate within f_cV's support.
                const double Ts = f.series().evaluate(lambdaF, r.lambdaC).T;
                const double Tc = f.contractile().evaluate(r.lambdaC, r.lambdaCRate, alpha).T;
                if (r.status == HillSolveStatus::Taut) {
                  EXPECT_NEAR(Ts, Tc, 1e-8 * kT0max);
                } else {
                  ++onJump;
                  const double d = 1e-12;
                  const double below =
                      f.contractile().evaluate(r.lambdaC - d, (r.lambdaC - d - lambdaCOld) / dt, alpha).T;
                  const double above =
                      f.contractile().evaluate(r.lambdaC + d, (r.lambdaC + d - lambdaCOld) / dt, alpha).T;
                  EXPECT_GE(Ts, std::min(below, above) - 1e-8 * kT0max);
                  EXPECT_LE(Ts, std::max(below, above) + 1e-8 * kT0max);
                  EXPECT_GT(std::abs(above - below), 1e-8 * kT0max);  // a real jump
                }
                EXPECT_GE(Ts, 0.0);
                EXPECT_NEAR(r.Ts, Ts, 1e-12 * kT0max);
                EXPECT_LE(r.lambdaC, lambdaF);
                EXPECT_GT(r.lambdaC, lambdaF / 1.03);
                EXPECT_GE(r.lambdaCRate, -10.0 - 1e-9);
                EXPECT_GT(cAtFibre.T, 0.0);
              } else {
                ++slack;
                EXPECT_EQ(cAtFibre.T, 0.0);
                EXPECT_EQ(r.Ts, 0.0);
                EXPECT_GE(r.lambdaC, lambdaF);
                if (alpha * T0s > 0.0)
                  EXPECT_GE(r.lambdaCRate, -10.0 - 1e-9);  // at most vmax
                else
                  EXPECT_EQ(r.lambdaC, lambdaF);  // an inactive element follows the fibre
              }
              EXPECT_NEAR(r.T, r.Tp + r.Ts, 1e-12 * kT0max);
            }
    }
  EXPECT_GT(taut, 300);
  EXPECT_GT(slack, 300);
  EXPECT_GT(onJump, 0);  // the paper set's discontinuous curves are exercised
}

// Consistent tangent dT_f/dlambda_f against central differences at fixed history.
TEST(HillMuscleFibre, TangentMatchesFiniteDifferences) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0;
  for (const ContractileCurves &curves : {paperTableIICurves(), physiologicalCurves()})
    for (int sample = 0; sample < 200; ++sample) {
      const HillMuscleFibre f = fibre(sample % 2 ? 1.0 : 0.1, curves);
      const double lambdaF = 0.6 + 1.2 * unit(rng);
      const HillFibreInput in{lambdaF, unit(rng), std::pow(10.0, -5.0 + 4.0 * unit(rng)),
                              lambdaF * (0.96 + 0.06 * unit(rng))};
      const HillFibreResponse r = f.evaluate(in);
      ASSERT_TRUE(succeeded(r.status)) << describe(r.status);
      const double h = 1e-7 * lambdaF;
      HillFibreInput plus = in, minus = in;
      plus.lambdaF += h;
      minus.lambdaF -= h;
      const HillFibreResponse rp = f.evaluate(plus), rm = f.evaluate(minus);
      if (rp.status != r.status || rm.status != r.status) continue;  // across the taut/slack switch
      const double fd = (rp.T - rm.T) / (2 * h);
      EXPECT_NEAR(r.dTdLambdaF, fd, 1e-6 * (std::abs(fd) + kT0max)) << "sample " << sample;
      ++checked;
    }
  EXPECT_GT(checked, 380);
}

// The root's slope d lambda_c / d lambda_f (implicit differentiation) against central differences
// of the roots; and a solve started from a nearby root moved along that slope (what a Newton
// iteration's point law does within a step) finds the same root in fewer local iterations than
// one started from the nearby root itself.
TEST(HillMuscleFibre, RootSlopeMatchesFiniteDifferencesAndPredictsTheNextRoot) {
  std::mt19937 rng(57);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0, plainIterations = 0, predictedIterations = 0;
  for (const ContractileCurves &curves : {paperTableIICurves(), physiologicalCurves()})
    for (int sample = 0; sample < 200; ++sample) {
      const HillMuscleFibre f = fibre(sample % 2 ? 1.0 : 0.1, curves);
      const double lambdaF = 0.7 + 0.8 * unit(rng);
      const HillFibreInput in{lambdaF, 0.05 + 0.95 * unit(rng), std::pow(10.0, -4.0 + 3.0 * unit(rng)),
                              lambdaF * (0.97 + 0.04 * unit(rng))};
      const HillFibreResponse r = f.evaluate(in);
      if (r.status != HillSolveStatus::Taut || !std::isfinite(r.dLambdaCdLambdaF)) continue;
      // Central differences at h and h/2, Richardson-extrapolated (error O(h^4)): the curves'
      // steep terms (B = 90 over |d|^2) leave O(h^2) at 1e-6 relative with h = 1e-6.
      auto central = [&](double h, bool &sameBranch) {
        HillFibreInput plus = in, minus = in;
        plus.lambdaF += h;
        minus.lambdaF -= h;
        const HillFibreResponse rp = f.evaluate(plus), rm = f.evaluate(minus);
        sameBranch = sameBranch && rp.status == r.status && rm.status == r.status;
        return (rp.lambdaC - rm.lambdaC) / (2 * h);
      };
      bool sameBranch = true;
      const double h = 1e-5 * lambdaF;
      const double coarse = central(h, sameBranch), fine = central(0.5 * h, sameBranch);
      // A kink of a curve within h (the p = 1 term of f_cL at lambda_c = 1.325): the differences
      // then disagree at first order, and neither is a derivative.
      if (!sameBranch || std::abs(coarse - fine) > 1e-4 * (std::abs(fine) + 1.0)) continue;
      const double fd = (4.0 * fine - coarse) / 3.0;
      EXPECT_NEAR(r.dLambdaCdLambdaF, fd, 1e-6 * (std::abs(fd) + 1.0)) << "sample " << sample;
      // The next Newton iterate's fibre stretch, 1e-3 away: started plain and predicted.
      HillFibreInput next = in;
      next.lambdaF = lambdaF * (1.0 + 1e-3);
      const HillFibreResponse reference = f.evaluate(next);
      if (reference.status != HillSolveStatus::Taut) continue;
      next.lambdaCStart = r.lambdaC;
      const HillFibreResponse plain = f.evaluate(next);
      next.lambdaCStart = r.lambdaC + r.dLambdaCdLambdaF * (next.lambdaF - lambdaF);
      const HillFibreResponse predicted = f.evaluate(next);
      ASSERT_EQ(predicted.status, HillSolveStatus::Taut);
      EXPECT_NEAR(predicted.lambdaC, reference.lambdaC, 1e-13) << "sample " << sample;
      EXPECT_NEAR(plain.lambdaC, reference.lambdaC, 1e-13) << "sample " << sample;
      plainIterations += plain.iterations;
      predictedIterations += predicted.iterations;
      ++checked;
    }
  EXPECT_GT(checked, 300);
  EXPECT_LT(predictedIterations, 0.85 * plainIterations) << plainIterations << " against " << predictedIterations;
}

// Isometric activation (lambda_f = 1, u = 1 from rest): the fibre tension is the contractile
// tension at every step, T = T0s T0max alpha_n f_cL(lambda_c) f_cV(rate), alpha_n follows
// 1 - exp(-t/tau_R) within the backward-Euler bound, and the tension history converges at first
// order as dt shrinks.
TEST(HillMuscleFibre, IsometricActivationFollowsTheActivationOde) {
  const double T0s = 0.1, tau = 0.150, tEnd = 0.5;
  const HillMuscleFibre f = fibre(T0s, physiologicalCurves());
  const ActivationDynamics activation;
  auto run = [&](double dt, std::vector<double> *tensionAtSamples) {
    double alpha = 0.0, lambdaC = 1.0, maxAlphaError = 0.0;
    const int n = static_cast<int>(std::lround(tEnd / dt)), every = static_cast<int>(std::lround(0.05 / dt));
    for (int k = 1; k <= n; ++k) {
      alpha = activation.step(alpha, 1.0, dt);
      const HillFibreResponse r = f.evaluate({1.0, alpha, dt, lambdaC});
      EXPECT_EQ(r.status, HillSolveStatus::Taut);
      const double fL = f.contractile().curves().forceLength->evaluate(r.lambdaC).value;
      const double fV = f.contractile().curves().forceVelocity->evaluate(r.lambdaCRate).value;
      EXPECT_NEAR(r.T, T0s * kT0max * alpha * fL * fV, 1e-9 * kT0max);
      // The contractile element's own length and rate change cost at most 4 % of T0s T0max alpha.
      EXPECT_LE(r.T, T0s * kT0max * alpha * (1 + 1e-12));
      EXPECT_GE(r.T, 0.96 * T0s * kT0max * alpha);
      maxAlphaError = std::max(maxAlphaError, std::abs(alpha - (1 - std::exp(-k * dt / tau))));
      if (k % every == 0 && tensionAtSamples) tensionAtSamples->push_back(r.T);
      lambdaC = r.lambdaC;
    }
    EXPECT_LE(maxAlphaError, dt / (2 * std::exp(1.0) * tau) * (1 + dt / tau));
    return maxAlphaError;
  };
  std::vector<double> reference;
  run(5e-3 / 64, &reference);
  double previous = 0.0;
  for (double dt : {5e-3, 2.5e-3, 1.25e-3}) {
    std::vector<double> samples;
    run(dt, &samples);
    ASSERT_EQ(samples.size(), reference.size());
    double error = 0.0;
    for (std::size_t i = 0; i < samples.size(); ++i)
      error = std::max(error, std::abs(samples[i] - reference[i]));
    if (previous > 0.0) EXPECT_NEAR(previous / error, 2.0, 0.3) << "dt " << dt;
    previous = error;
  }
  EXPECT_NEAR(reference.back() / (T0s * kT0max), 1 - std::exp(-tEnd / tau), 0.01);
}

// Isotonic contractions (fully active, load held by Newton on lambda_f with the consistent
// tangent): the steady contractile velocity, measured from the fibre length, satisfies the
// force-velocity law: shortening under loads below the isometric tension, lengthening above.
TEST(HillMuscleFibre, IsotonicContractionsFollowTheForceVelocityLaw) {
  const HillMuscleFibre f = fibre(1.0, physiologicalCurves());
  const double dt = 1e-3;
  // Isometric at lambda_f = 1 to steady state.
  double lambdaC = 1.0;
  HillFibreResponse iso;
  for (int k = 0; k < 400; ++k) {
    iso = f.evaluate({1.0, 1.0, dt, lambdaC});
    lambdaC = iso.lambdaC;
  }
  ASSERT_EQ(iso.status, HillSolveStatus::Taut);
  EXPECT_NEAR(iso.lambdaCRate, 0.0, 1e-6);
  const double Tiso = iso.T;
  double previousVelocity = -1e9;
  ScalarSolveOptions options;
  options.residualTolerance = 1e-10 * kT0max;
  const BracketedNewtonSolver solver(options);
  int newtonIterations = 0;
  for (double k : {0.2, 0.5, 0.8, 1.0, 1.1, 1.25}) {
    double lambdaF = 1.0, lc = lambdaC;
    std::vector<double> history;
    HillFibreResponse r;
    for (int step = 0; step < 40; ++step) {
      // T_f(lambda_f) = k Tiso, Newton on lambda_f with the consistent tangent (safeguarded).
      const auto load = solver.solve(
          [&](double x) {
            const HillFibreResponse q = f.evaluate({x, 1.0, dt, lc});
            return ValueSlope{q.T - k * Tiso, q.dTdLambdaF};
          },
          0.5, 2.0, lambdaF);
      ASSERT_EQ(load.status, ScalarSolveStatus::Converged) << "load " << k << " step " << step;
      lambdaF = load.x;
      r = f.evaluate({lambdaF, 1.0, dt, lc});
      ASSERT_TRUE(succeeded(r.status));
      ASSERT_NEAR(r.T, k * Tiso, 1e-9 * kT0max) << "load " << k;
      if (step > 0) newtonIterations = std::max(newtonIterations, load.iterations);
      lc = r.lambdaC;
      history.push_back(lambdaF);
    }
    // Steady contractile velocity from the last 10 ms of fibre length (the series stretch is
    // constant once the load is), against the Hill / van Soest-Bobbert target at the contractile
    // force ratio T_s / (T0max f_cL(lambda_c)).
    const double lambdaS = lambdaF / lc;
    const double velocity = (history.back() - history[history.size() - 11]) / (10 * dt) / lambdaS;
    const double forceRatio = r.Ts / (kT0max * f.contractile().curves().forceLength->evaluate(lc).value);
    EXPECT_NEAR(hillAndVanSoest(velocity), forceRatio, kForceVelocityFitResidual + 2e-3) << "load " << k;
    EXPECT_GT(velocity, previousVelocity);
    if (k < 1.0) EXPECT_LT(velocity, -0.1);
    if (k == 1.0) EXPECT_NEAR(velocity, 0.0, 0.02);
    if (k > 1.0) EXPECT_GT(velocity, 0.02);
    previousVelocity = velocity;
  }
  EXPECT_LE(newtonIterations, 8);  // the consistent tangent keeps the load control quadratic
}

// Quick release: a 5 % step shortening of an isometrically active fibre slackens the series
// element; the contractile element then shortens at its maximum speed (10 /s) with no force until
// the series element is taut again, after which the tension redevelops.
TEST(HillMuscleFibre, QuickReleaseShortensAtMaximumSpeedThenRedevelops) {
  const HillMuscleFibre f = fibre(1.0, physiologicalCurves());
  const double dt = 1e-3;
  double lambdaC = 1.0;
  for (int k = 0; k < 300; ++k) lambdaC = f.evaluate({1.0, 1.0, dt, lambdaC}).lambdaC;
  ASSERT_GT(lambdaC, 0.95);  // the series stretch 1/lambda_c is smaller than the 5 % release
  const double lambdaF = 0.95;
  HillFibreResponse r = f.evaluate({lambdaF, 1.0, dt, lambdaC});
  EXPECT_EQ(r.status, HillSolveStatus::Slack);
  EXPECT_EQ(r.T, 0.0);
  EXPECT_NEAR(r.lambdaCRate, -10.0, 1e-9);
  int slackSteps = 0;
  double previousT = 0.0;
  for (int k = 0; k < 600; ++k) {
    if (r.status == HillSolveStatus::Slack)
      ++slackSteps;
    else
      EXPECT_GE(r.T, previousT - 1e-6 * kT0max);  // tension redevelops monotonically
    previousT = r.T;
    lambdaC = r.lambdaC;
    r = f.evaluate({lambdaF, 1.0, dt, lambdaC});
  }
  EXPECT_GE(slackSteps, 1);
  EXPECT_LE(slackSteps, 3);  // (lambda_c_old - 0.95) / (10 dt) steps at most
  const double fL = f.contractile().curves().forceLength->evaluate(r.lambdaC).value;
  EXPECT_NEAR(r.T, kT0max * fL, 1e-3 * kT0max);  // isometric again at the new length
}

TEST(HillMuscleFibre, InvalidInputIsReported) {
  const HillMuscleFibre f = fibre(1.0, physiologicalCurves());
  for (const HillFibreInput &in : {HillFibreInput{0.0, 0.5, 0.01, 1.0}, HillFibreInput{NAN, 0.5, 0.01, 1.0},
                                   HillFibreInput{1.0, 1.5, 0.01, 1.0}, HillFibreInput{1.0, -0.1, 0.01, 1.0},
                                   HillFibreInput{1.0, 0.5, 0.0, 1.0}, HillFibreInput{1.0, 0.5, 0.01, -1.0}})
    EXPECT_EQ(f.evaluate(in).status, HillSolveStatus::InvalidInput);
  for (auto s : {HillSolveStatus::Taut, HillSolveStatus::Slack, HillSolveStatus::InvalidInput,
                 HillSolveStatus::InvalidBracket, HillSolveStatus::NonFinite, HillSolveStatus::MaxIterations,
                 HillSolveStatus::OnCurveJump, HillSolveStatus::SingularTangent})
    EXPECT_NE(std::string(describe(s)), "?");
  EXPECT_THROW(ContractileElement(kT0max, 1.5, physiologicalCurves()), std::invalid_argument);
  EXPECT_THROW(ContractileElement(kT0max, 0.5, ContractileCurves{}), std::invalid_argument);
}

// Vanishing activation (a step ending just past the start of a neural-input ramp: alpha ~ 1e-16,
// or underflowed to 1e-300, a denormal or 0): the local solve succeeds and the fibre tends to its
// parallel element continuously, T_s <= T0s T0max alpha max(f_cL f_cV) and dT_s/dlambda_f bounded
// by the contractile element's stiffness, both -> 0 with alpha, at every stretch and stretch rate.
TEST(HillMuscleFibre, VanishingActivationGivesThePassiveResponse) {
  const ParallelElement p = ParallelElement::tableI();
  int taut = 0;
  for (const ContractileCurves &curves : {paperTableIICurves(), physiologicalCurves()})
    for (double T0s : {0.1, 1.0}) {
      const HillMuscleFibre f = fibre(T0s, curves);
      for (double alpha : {1e-16, 1e-300, 4.9e-324, 1e-310, 0.0})
        for (double lambdaF : {0.7, 1.0, 1.3})
          for (double dt : {1e-6, 1e-3})
            for (double oldOverF : {0.999, 1.0, 1.001, 1.02}) {
              const HillFibreInput in{lambdaF, alpha, dt, lambdaF * oldOverF};
              const HillFibreResponse r = f.evaluate(in);
              ASSERT_TRUE(succeeded(r.status)) << describe(r.status) << " alpha " << alpha << " lambda_f "
                                               << lambdaF << " dt " << dt << " lambda_c_old " << in.lambdaCOld;
              if (r.status == HillSolveStatus::Taut) ++taut;
              const FibreTension passive = p.evaluate(lambdaF);
              EXPECT_GE(r.Ts, 0.0);
              EXPECT_LE(r.Ts, 1.01 * kT0max * alpha * f.contractile().capacityBound());
              EXPECT_NEAR(r.T, passive.T + r.Ts, 1e-12 * kT0max);
              // dT_s/dlambda_f <= |dT_c/dlambda_c| + |dT_c/drate| / dt at the root (series in series
              // with the contractile element); at alpha <= 1e-16 below 1e-9 T0max for dt >= 1e-6.
              EXPECT_NEAR(r.dTdLambdaF, passive.dTdLambda, 1e-9 * kT0max);
              if (r.status == HillSolveStatus::Taut) {
                EXPECT_LE(r.lambdaC, lambdaF);
                EXPECT_GE(r.lambdaC, lambdaF * (1 - 1e-11));  // the series element barely stretches
              } else {  // slack: shortening faster than v_max, or alpha T0s rounds to 0
                EXPECT_EQ(r.Ts, 0.0);
                EXPECT_GE(r.lambdaC, lambdaF);
              }
            }
    }
  EXPECT_GT(taut, 0);
}
