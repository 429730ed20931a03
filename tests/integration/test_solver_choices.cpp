// The deck's solver choices give the same answer (MueLu, Ifpack2 alone, MUMPS and Amesos2 KLU2
// direct, and auto, which solves this small block directly), and a
// step that fails (the whole 400 MPa load in one step) is cut back and recovered, never a crash.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "RunDeck.hpp"

using namespace glossa;

namespace {
// deal.II step-44, 4 elements per side, t = 1 (doc/verification/step44_reference.md).
constexpr double kDealII4 = -0.789713e-3;

double topCentre(const nlohmann::json &summary) {
  return summary.at("final_displacement").at("top_centre").at(1).get<double>();
}
} // namespace

TEST(SolverChoices, MueLuIfpack2AndDirectAgree) {
  const std::string deck = test::inputPath("verification/step44_block.xml");
  for (const char *choice : {"Linear solver/type=iterative", "Linear solver/preconditioner=Ifpack2",
                             "Linear solver/type=direct", "Linear solver/direct solver=KLU2", "Linear solver/type=auto"}) {
    const auto s = test::runDeck(deck, {"Mesh/Box/cells=4,4,4", choice}, test::scratchDirectory("choice"));
    ASSERT_TRUE(s.at("converged").get<bool>()) << choice;
    EXPECT_NEAR(topCentre(s), kDealII4, 1e-5 * std::abs(kDealII4)) << choice;
  }
}

// auto: a direct solve (one Krylov iteration per Newton iteration when every tangent is factored:
// the factorisation is the exact inverse inside the Krylov method) up to 'direct up to' unknowns (375 here), the iterative solver
// above (MueLu with a coarse size of 50, so that it is not itself a direct solve of 375 rows); the
// same answer either way.
TEST(SolverChoices, AutoSolvesSmallSystemsDirectlyAndLargerOnesIteratively) {
  const std::string deck = test::inputPath("verification/step44_block.xml");
  auto krylovPerNewton = [](const nlohmann::json &s) {
    double newton = 0.0, krylov = 0.0;
    for (const auto &step : s.at("steps")) {
      newton += step.at("newton_iterations").get<double>();
      krylov += step.at("linear_iterations").get<double>();
    }
    return krylov / newton;
  };
  const auto direct = test::runDeck(deck, {"Mesh/Box/cells=4,4,4", "Linear solver/direct up to=375",
                                           "Linear solver/direct reuse iterations=0"},
                                    test::scratchDirectory("auto_direct"));
  const auto iterative = test::runDeck(deck, {"Mesh/Box/cells=4,4,4", "Linear solver/direct up to=374",
                                                  "Linear solver/coarse size=50"},
                                       test::scratchDirectory("auto_iterative"));
  ASSERT_TRUE(direct.at("converged").get<bool>());
  ASSERT_TRUE(iterative.at("converged").get<bool>());
  EXPECT_EQ(krylovPerNewton(direct), 1.0);
  EXPECT_GT(krylovPerNewton(iterative), 3.0);
  EXPECT_NEAR(topCentre(direct), kDealII4, 1e-5 * std::abs(kDealII4));
  EXPECT_NEAR(topCentre(iterative), kDealII4, 1e-5 * std::abs(kDealII4));
}

// Iterative settings a deck gives while auto solves directly would pass silently: each is named in
// summary.json's warnings (and on stderr), with where it was given; the iterative run that uses
// them has none.
TEST(SolverChoices, AutoNamesTheIterativeSettingsItDoesNotUse) {
  const std::string deck = test::inputPath("verification/step44_block.xml");
  const auto direct = test::runDeck(deck, {"Mesh/Box/cells=2,2,2", "Time/end time=0.1", "Linear solver/preconditioner=Ifpack2",
                                           "Linear solver/smoother degree=3"},
                                    test::scratchDirectory("auto_direct_warned"));
  ASSERT_TRUE(direct.at("converged").get<bool>());
  ASSERT_TRUE(direct.contains("warnings"));
  ASSERT_EQ(direct.at("warnings").size(), 2u);
  const std::string first = direct["warnings"][0], second = direct["warnings"][1];
  EXPECT_NE(first.find("'Linear solver/preconditioner' is not used"), std::string::npos) << first;
  EXPECT_NE(first.find("--set on the command line"), std::string::npos) << first;
  EXPECT_NE(second.find("'Linear solver/smoother degree'"), std::string::npos) << second;
  const auto iterative = test::runDeck(deck, {"Mesh/Box/cells=2,2,2", "Time/end time=0.1", "Linear solver/type=iterative",
                                              "Linear solver/preconditioner=Ifpack2", "Linear solver/smoother degree=3"},
                                       test::scratchDirectory("iterative_not_warned"));
  ASSERT_TRUE(iterative.at("converged").get<bool>());
  EXPECT_FALSE(iterative.contains("warnings"));
}

// direct ordering: every fill-reducing ordering factors the same tangent, so the answer is deal.II's
// with each, and summary.json names the one MUMPS used. auto leaves the 375 unknowns of the 4^3
// block to MUMPS's own choice (PORD would end the process on a single element) and takes PORD from
// 1,000: on the 8^3 block (2,187 unknowns) its factorisation needs fewer flops than AMF's, the
// ordering MUMPS itself picks there (measured 0.58x; doc/performance.md, "The direct solver's
// ordering"). Flops and entries are counts, not times: the same on any machine.
TEST(SolverChoices, EveryOrderingGivesTheAnswerAndAutoTakesPordOnLargerTangents) {
  const std::string deck = test::inputPath("verification/step44_block.xml");
  auto run = [&](const std::string &cells, const std::string &ordering) {
    return test::runDeck(deck, {"Mesh/Box/cells=" + cells, "Linear solver/type=direct",
                                "Linear solver/direct ordering=" + ordering},
                         test::scratchDirectory("ordering_" + ordering));
  };
  for (const char *ordering : {"PORD", "AMD", "AMF", "QAMD"}) {
    const auto s = run("4,4,4", ordering);
    ASSERT_TRUE(s.at("converged").get<bool>()) << ordering;
    EXPECT_NEAR(topCentre(s), kDealII4, 1e-5 * std::abs(kDealII4)) << ordering;
    EXPECT_EQ(s.at("direct_factors").at("ordering").get<std::string>(), ordering);
  }
  const auto small = run("4,4,4", "auto");
  ASSERT_TRUE(small.at("converged").get<bool>());
  EXPECT_NE(small.at("direct_factors").at("ordering").get<std::string>(), "PORD");

  const auto pord = run("8,8,8", "auto"), amf = run("8,8,8", "AMF");
  ASSERT_TRUE(pord.at("converged").get<bool>());
  ASSERT_TRUE(amf.at("converged").get<bool>());
  EXPECT_EQ(pord.at("direct_factors").at("ordering").get<std::string>(), "PORD");
  EXPECT_LT(pord.at("direct_factors").at("flops").get<double>(), 0.8 * amf.at("direct_factors").at("flops").get<double>());
  EXPECT_LT(pord.at("direct_factors").at("entries").get<double>(), amf.at("direct_factors").at("entries").get<double>());
  EXPECT_NEAR(topCentre(pord), topCentre(amf), 1e-8 * std::abs(topCentre(amf)));
}

// direct reuse iterations = 10: the factors of a Newton solve's first tangent precondition its
// later iterations (more than one Krylov iteration per solve), and the answer stays deal.II's.
TEST(SolverChoices, AReusedFactorisationPreconditionsLaterNewtonIterations) {
  const auto s = test::runDeck(test::inputPath("verification/step44_block.xml"),
                               {"Mesh/Box/cells=4,4,4", "Linear solver/type=direct", "Linear solver/direct reuse iterations=10"},
                               test::scratchDirectory("direct_reuse"));
  ASSERT_TRUE(s.at("converged").get<bool>());
  double newton = 0.0, krylov = 0.0;
  for (const auto &step : s.at("steps")) {
    newton += step.at("newton_iterations").get<double>();
    krylov += step.at("linear_iterations").get<double>();
  }
  EXPECT_GT(krylov, newton);
  EXPECT_NEAR(topCentre(s), kDealII4, 1e-5 * std::abs(kDealII4));
}

// direct reuse scope = step: the factors of a step's first tangent also precondition the Newton
// solves of its later Uzawa iterations (the multipliers change the tangent little), so a step
// factors fewer tangents than with a fresh factorisation per Newton solve, still at least one (each
// step starts afresh, which keeps restarts deterministic); the answer is the fresh factors' to the
// solver's tolerances.
TEST(SolverChoices, FactorsKeptForAStepServeItsUzawaIterations) {
  auto run = [](const char *scope) {
    return test::runDeck(test::inputPath("verification/step44_block.xml"),
                         {"Mesh/Box/cells=4,4,4", "Linear solver/type=direct", "Incompressibility/method=augmented Lagrangian",
                          std::string("Linear solver/direct reuse scope=") + scope},
                         test::scratchDirectory(std::string("direct_scope_") + (scope[0] == 'N' ? "newton" : scope)));
  };
  const auto perSolve = run("Newton solve"), perStep = run("step");
  ASSERT_TRUE(perSolve.at("converged").get<bool>());
  ASSERT_TRUE(perStep.at("converged").get<bool>());
  auto factorisations = [](const nlohmann::json &s) {
    return s.at("time_split").at("direct_factorisation").at("calls").get<int>();
  };
  // A Newton solve that tightens the loop's inexact one (nothing moved between) keeps its factors
  // in either scope; every other solve refactors under 'Newton solve'.
  int newtonSolves = 0, freshSolves = 0;
  for (const auto &step : perSolve.at("steps"))
    for (const auto &solve : step.at("newton_solves")) {
      ++newtonSolves;
      if (!solve.at("continues_last_solve").get<bool>()) ++freshSolves;
    }
  const int steps = static_cast<int>(perStep.at("steps").size());
  ASSERT_GT(freshSolves, steps); // multiplier updates: more than one fresh Newton solve per step
  EXPECT_GE(factorisations(perSolve), freshSolves);
  EXPECT_LT(factorisations(perSolve), newtonSolves + 1);
  EXPECT_GE(factorisations(perStep), steps);
  EXPECT_LT(factorisations(perStep), factorisations(perSolve));
  EXPECT_NEAR(topCentre(perStep), topCentre(perSolve), 1e-8 * std::abs(topCentre(perSolve)));
}

// A fixed component holds its prescribed value exactly, whatever the linear solver: its Newton
// update solves a diagonal row with a zero right-hand side, which CG with MueLu meets only to its
// tolerance (before: top_centre, on the x = 0 and z = 0 symmetry planes, moved by ux = -4.9e-12,
// uz = -2.6e-11 m on the 8^3 block with the augmented Lagrangian; MUMPS gave 0).
TEST(SolverChoices, FixedComponentsHoldExactlyWithAnIterativeSolver) {
  const std::vector<std::string> iterativeAL = {"Mesh/Box/cells=8,8,8", "Incompressibility/method=augmented Lagrangian",
                                                "Linear solver/type=iterative"};
  const auto dir = test::scratchDirectory("dirichlet_iterative");
  const auto s = test::runDeck(test::inputPath("verification/step44_block.xml"), iterativeAL, dir);
  ASSERT_TRUE(s.at("converged").get<bool>());
  EXPECT_GT(s.at("steps").at(0).at("linear_iterations").get<int>(), 10) << "not an iterative solve";
  int rows = 0;
  for (const auto &r : test::readTraces(dir / "traces.csv")) {
    if (r.point != "top_centre") continue;
    ++rows;
    EXPECT_EQ(r.u[0], 0.0) << "t = " << r.time; // x = 0: symmetry x
    EXPECT_EQ(r.u[2], 0.0) << "t = " << r.time; // z = 0: symmetry z
  }
  EXPECT_EQ(rows, 11); // t = 0 and 10 steps
  EXPECT_EQ(s.at("final_displacement").at("top_centre").at(0).get<double>(), 0.0);
  EXPECT_EQ(s.at("final_displacement").at("top_centre").at(2).get<double>(), 0.0);
}

// A ramp of duration 0 spans the deck's own end time: a run shortened by --set "Time/end
// time=0.3" is the first 0.3 s of the deck's run (before, the ramp was compressed into 0.3 s and
// the whole load applied).
TEST(TimeStepping, AShortenedRunIsTheStartOfTheDecksRun) {
  const std::string deck = test::inputPath("verification/step44_block.xml");
  const auto fullDir = test::scratchDirectory("ramp_full"), shortDir = test::scratchDirectory("ramp_short");
  const auto full = test::runDeck(deck, {"Mesh/Box/cells=4,4,4"}, fullDir);
  const auto shortened = test::runDeck(deck, {"Mesh/Box/cells=4,4,4", "Time/end time=0.3"}, shortDir);
  ASSERT_TRUE(full.at("converged").get<bool>() && shortened.at("converged").get<bool>());
  const auto trace = test::traceOf(test::readTraces(fullDir / "traces.csv"), "top_centre", 1);
  const auto at03 = std::min_element(trace.begin(), trace.end(), [](const auto &a, const auto &b) {
    return std::abs(a.first - 0.3) < std::abs(b.first - 0.3);
  });
  ASSERT_NEAR(at03->first, 0.3, 1e-12);
  EXPECT_NEAR(topCentre(shortened), at03->second, 1e-9 * std::abs(at03->second));
  EXPECT_LT(std::abs(topCentre(shortened)), 0.5 * std::abs(topCentre(full))) << "the whole load was applied";
}

TEST(TimeStepping, AFailedStepIsCutBackAndRecovered) {
  const auto s = test::runDeck(test::inputPath("verification/step44_block.xml"),
                               {"Mesh/Box/cells=4,4,4", "Time/step size=1"}, test::scratchDirectory("cutback"));
  ASSERT_TRUE(s.at("converged").get<bool>());
  EXPECT_GT(s.at("steps").size(), 1u) << "the full load in one step should have needed cut-backs";
  EXPECT_NEAR(topCentre(s), kDealII4, 1e-5 * std::abs(kDealII4));
}

TEST(TimeStepping, AnExtrapolatedStartThatFailsIsTriedAgainFromTheCommittedState) {
  // The protrusion scene's first step is cut back to an eighth (the muscles' jump from rest);
  // extrapolating that jump into the next step inverts elements. The step is then solved from
  // the committed state at the same size instead of being cut back: as many steps as without the
  // predictor, and the same answer to within the tolerances of either run.
  const std::string deck = test::inputPath("paper/s8_4_protrusion.xml");
  const auto plain = test::runDeck(deck, {"Output/fields=false", "Time/predictor=none"},
                                   test::scratchDirectory("protrusion_no_predictor"));
  const auto predicted = test::runDeck(deck, {"Output/fields=false", "Time/predictor=linear extrapolation"},
                                       test::scratchDirectory("protrusion_predictor"));
  ASSERT_TRUE(plain.at("converged").get<bool>() && predicted.at("converged").get<bool>());
  EXPECT_GT(predicted.value("predictor_retries", 0), 0) << "no extrapolated start failed: the retry was not exercised";
  EXPECT_EQ(plain.value("predictor_retries", 0), 0);
  EXPECT_EQ(predicted.at("steps").size(), plain.at("steps").size());
  double largest = 0.0, deviation = 0.0;
  for (const auto &[name, u] : plain.at("final_displacement").items())
    for (int i = 0; i < 3; ++i) {
      const double a = u.at(i).get<double>(), b = predicted.at("final_displacement").at(name).at(i).get<double>();
      largest = std::max(largest, std::abs(a));
      deviation = std::max(deviation, std::abs(a - b));
    }
  EXPECT_GT(largest, 1e-3) << "the tongue tip moves by millimetres";
  EXPECT_LT(deviation, 1e-4 * largest);
}

TEST(TimeStepping, ARunThatCannotConvergeStopsCleanlyWithItsReason) {
  // One Newton iteration allowed and no room to cut back: the run must stop, say why, and leave
  // a readable summary.
  const auto dir = test::scratchDirectory("nonconvergent");
  const auto s = test::runDeck(test::inputPath("verification/step44_block.xml"),
                               {"Mesh/Box/cells=2,2,2", "Nonlinear solver/maximum iterations=1", "Time/minimum step size=0.05"},
                               dir);
  EXPECT_FALSE(s.at("converged").get<bool>());
  EXPECT_NE(s.at("failure").get<std::string>().find("below the minimum step size"), std::string::npos);
  std::ifstream in(dir / "summary.json");
  const auto onDisk = nlohmann::json::parse(in);
  EXPECT_FALSE(onDisk.at("converged").get<bool>());
  EXPECT_FALSE(onDisk.at("running").get<bool>());
}
