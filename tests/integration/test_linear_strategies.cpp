// Every linear-solver strategy of the deck's "Linear solver" section solves the nearly
// incompressible step-44 block (nu = 0.4999, 4 elements per side) to deal.II step-44's
// displacement; a coarse size of 50 rows makes MueLu build a real hierarchy on this small mesh so
// that the smoother under test does the work. The Stratimikos lists are checked to be what the
// deck asks for, so a strategy cannot silently fall back to another.
#include <gtest/gtest.h>

#include <cmath>

#include "RunDeck.hpp"
#include "solvers/linear/LinearSolverFactory.hpp"

using namespace glossa;

namespace {
// deal.II step-44, 4 elements per side, t = 1 (doc/verification/step44_reference.md).
constexpr double kDealII4 = -0.789713e-3;

double topCentre(const nlohmann::json &s) {
  return s.at("final_displacement").at("top_centre").at(1).get<double>();
}

int totalKrylov(const nlohmann::json &s) {
  int n = 0;
  for (const auto &step : s.at("steps")) n += step.at("linear_iterations").get<int>();
  return n;
}

Teuchos::ParameterList mueluList(const std::vector<std::string> &overrides) {
  const auto schema = app::deckSchema();
  auto deck = io::Deck::fromFile(test::inputPath("verification/step44_block.xml"));
  for (const auto &o : overrides) deck.applyOverride(o, schema);
  deck.validate(schema);
  const auto p = solvers::stratimikosParameters(solvers::parseLinearSolverParameters(deck.root().sublist("Linear solver")), {});
  return p->sublist("Preconditioner Types").sublist("MueLu");
}
}  // namespace

class LinearStrategy : public ::testing::TestWithParam<std::vector<std::string>> {};

namespace {
std::string instance() {
  std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  return name.substr(name.find('/') + 1);
}
} // namespace

TEST_P(LinearStrategy, SolvesTheBlockToTheDealIIReference) {
  std::vector<std::string> o = {"Mesh/Box/cells=4,4,4", "Linear solver/type=iterative", "Linear solver/coarse size=50",
                                "Output/fields=false"};
  for (const auto &x : GetParam()) o.push_back(x);
  const auto s =
      // One directory per instance ("SolvesThe.../3"): ctest may run the instances concurrently.
      test::runDeck(test::inputPath("verification/step44_block.xml"), o, test::scratchDirectory("strategy_" + instance()));
  ASSERT_TRUE(s.at("converged").get<bool>()) << GetParam().front();
  EXPECT_NEAR(topCentre(s), kDealII4, 1e-5 * std::abs(kDealII4)) << GetParam().front();
  EXPECT_GT(totalKrylov(s), 0);
}

INSTANTIATE_TEST_SUITE_P(
    Smoothers, LinearStrategy,
    ::testing::Values(std::vector<std::string>{"Linear solver/MueLu smoother=Chebyshev"},
                      std::vector<std::string>{"Linear solver/MueLu smoother=symmetric Gauss-Seidel",
                                               "Linear solver/smoother degree=2"},
                      std::vector<std::string>{"Linear solver/MueLu smoother=node-block Gauss-Seidel"},
                      std::vector<std::string>{"Linear solver/MueLu smoother=vertex-patch"},
                      std::vector<std::string>{"Linear solver/MueLu smoother=vertex-patch",
                                               "Linear solver/vertex-patch levels=all"},
                      std::vector<std::string>{"Linear solver/preconditioner=FROSch"},
                      std::vector<std::string>{"Linear solver/preconditioner=FROSch",
                                               "Linear solver/FROSch coarse space=RGDSW"},
                      std::vector<std::string>{"Linear solver/MueLu reuse=none"},
                      std::vector<std::string>{"Linear solver/MueLu reuse=RAP"},
                      std::vector<std::string>{"Linear solver/MueLu reuse=full"},
                      std::vector<std::string>{"Linear solver/MueLu reuse scope=run"},
                      std::vector<std::string>{"Linear solver/MueLu reuse scope=Newton solve"},
                      std::vector<std::string>{"Linear solver/Chebyshev eigenvalue method=power"},
                      std::vector<std::string>{"Linear solver/MueLu reuse scope=run",
                                               "Incompressibility/method=augmented Lagrangian",
                                               "Incompressibility/dilatation tolerance=1e-7"}));

// The deck's MueLu reuse scope holds for MueLu only; every other solve is rebuilt per Newton solve.
TEST(LinearStrategyLists, OnlyAMueLuHierarchyOutlivesANewtonSolve) {
  const auto schema = app::deckSchema();
  auto section = [&](std::vector<std::string> overrides) {
    auto deck = io::Deck::fromFile(test::inputPath("verification/step44_block.xml"));
    for (const auto &o : overrides) deck.applyOverride(o, schema);
    deck.validate(schema);
    return solvers::parseLinearSolverParameters(deck.root().sublist("Linear solver"));
  };
  solvers::LinearSolverContext large;
  large.globalRows = 100000;
  using solvers::ReuseScope;
  EXPECT_EQ(solvers::keptReuseScope(section({}), large, false), ReuseScope::step);  // the default
  EXPECT_EQ(solvers::keptReuseScope(section({"Linear solver/MueLu reuse scope=run"}), large, false), ReuseScope::run);
  EXPECT_EQ(solvers::keptReuseScope(section({"Linear solver/MueLu reuse scope=run"}), large, true),
            ReuseScope::newtonSolve);
  EXPECT_EQ(solvers::keptReuseScope(section({"Linear solver/preconditioner=Ifpack2"}), large, false),
            ReuseScope::newtonSolve);
  solvers::LinearSolverContext small = large;
  small.globalRows = 2000;  // auto chooses the direct solve
  EXPECT_EQ(solvers::keptReuseScope(section({"Linear solver/type=auto"}), small, false), ReuseScope::newtonSolve);
}

TEST(LinearStrategyLists, EachSmootherIsWhatTheDeckSays) {
  {
    const auto m = mueluList(
        {"Linear solver/MueLu smoother=node-block Gauss-Seidel", "Linear solver/smoother degree=2"});
    EXPECT_EQ(m.get<std::string>("smoother: type"), "BLOCK RELAXATION");
    EXPECT_EQ(m.sublist("smoother: params").get<std::string>("partitioner: type"), "linear");
    EXPECT_EQ(m.sublist("smoother: params").get<int>("partitioner: overlap"), 0);
    EXPECT_EQ(m.sublist("smoother: params").get<int>("relaxation: sweeps"), 2);
    EXPECT_EQ(m.sublist("smoother: params").get<std::string>("relaxation: container"), "Dense");
    EXPECT_EQ(m.get<std::string>("reuse: type"), "RAP"); // the default
  }
  {
    const auto m = mueluList({"Linear solver/MueLu reuse=RP"});
    EXPECT_EQ(m.get<std::string>("reuse: type"), "RP");
  }
  {
    const auto m = mueluList({"Linear solver/MueLu smoother=vertex-patch"});
    EXPECT_EQ(m.get<std::string>("smoother: type"), "CHEBYSHEV");  // the coarse levels
    EXPECT_EQ(m.sublist("level 0").get<std::string>("smoother: type"), "BLOCK RELAXATION");
    EXPECT_EQ(m.sublist("level 0").sublist("smoother: params").get<int>("partitioner: overlap"), 1);
    EXPECT_EQ(m.get<std::string>("reuse: type"), "none");
  }
  {
    const auto m =
        mueluList({"Linear solver/MueLu smoother=vertex-patch", "Linear solver/vertex-patch levels=all"});
    EXPECT_EQ(m.get<std::string>("smoother: type"), "BLOCK RELAXATION");
    EXPECT_FALSE(m.isSublist("level 0"));
  }
  {
    const auto schema = app::deckSchema();
    auto deck = io::Deck::fromFile(test::inputPath("verification/step44_block.xml"));
    deck.applyOverride("Linear solver/preconditioner=FROSch", schema);
    deck.applyOverride("Linear solver/FROSch coarse space=RGDSW", schema);
    deck.validate(schema);
    const auto p = solvers::stratimikosParameters(solvers::parseLinearSolverParameters(deck.root().sublist("Linear solver")), {});
    EXPECT_EQ(p->get<std::string>("Preconditioner Type"), "FROSch");
    const auto &f = p->sublist("Preconditioner Types").sublist("FROSch");
    EXPECT_EQ(f.get<std::string>("CoarseOperator Type"), "RGDSWCoarseOperator");
    EXPECT_EQ(f.get<int>("DofsPerNode"), 3);
    EXPECT_EQ(f.sublist("AlgebraicOverlappingOperator").get<std::string>("Combine Values in Overlap"),
              "Full");
  }
  {
    const auto m = mueluList({"Linear solver/MueLu smoother=Chebyshev", "Linear solver/smoother degree=6",
                              "Linear solver/Chebyshev eigenvalue ratio=100"});
    EXPECT_EQ(m.get<std::string>("smoother: type"), "CHEBYSHEV");
    EXPECT_EQ(m.sublist("smoother: params").get<int>("chebyshev: degree"), 6);
    EXPECT_EQ(m.sublist("smoother: params").get<double>("chebyshev: ratio eigenvalue"), 100.0);
  }
  {
    // The eigenvalue estimate: Lanczos ("cg") with 15 steps by default, 50 power iterations when
    // the deck asks for the power method without a count, the deck's count when it gives one.
    const auto lanczos = mueluList({}).sublist("smoother: params");
    EXPECT_EQ(lanczos.get<std::string>("eigen-analysis: type"), "cg");
    EXPECT_EQ(lanczos.get<int>("chebyshev: eigenvalue max iterations"), 15);
    const auto power = mueluList({"Linear solver/Chebyshev eigenvalue method=power"}).sublist("smoother: params");
    EXPECT_EQ(power.get<std::string>("eigen-analysis: type"), "power method");
    EXPECT_EQ(power.get<int>("chebyshev: eigenvalue max iterations"), 50);
    const auto given = mueluList({"Linear solver/Chebyshev eigenvalue iterations=8"}).sublist("smoother: params");
    EXPECT_EQ(given.get<int>("chebyshev: eigenvalue max iterations"), 8);
  }
  {
    // A nonsymmetric tangent: Lanczos broke down there, so the power method with its 50 iterations.
    const auto schema = app::deckSchema();
    auto deck = io::Deck::fromFile(test::inputPath("verification/step44_block.xml"));
    deck.validate(schema);
    solvers::LinearSolverContext nonsymmetric;
    nonsymmetric.symmetric = false;
    const auto p = solvers::stratimikosParameters(
        solvers::parseLinearSolverParameters(deck.root().sublist("Linear solver")), nonsymmetric);
    const auto &sp = p->sublist("Preconditioner Types").sublist("MueLu").sublist("smoother: params");
    EXPECT_EQ(sp.get<std::string>("eigen-analysis: type"), "power method");
    EXPECT_EQ(sp.get<int>("chebyshev: eigenvalue max iterations"), 50);
  }
  {
    // Several ranks: the coarse levels, gathered onto one rank, by the power method (Lanczos broke
    // down there on one rank alone); the finest level, on every rank, keeps Lanczos. Iterative
    // asked for: 'auto' solves 375 unknowns directly on 2 ranks too.
    const auto schema = app::deckSchema();
    auto deck = io::Deck::fromFile(test::inputPath("verification/step44_block.xml"));
    deck.applyOverride("Linear solver/type=iterative", schema);
    deck.validate(schema);
    solvers::LinearSolverContext twoRanks;
    twoRanks.ranks = 2;
    twoRanks.globalRows = 375;
    const auto p = solvers::stratimikosParameters(
        solvers::parseLinearSolverParameters(deck.root().sublist("Linear solver")), twoRanks);
    const auto &m = p->sublist("Preconditioner Types").sublist("MueLu");
    EXPECT_EQ(m.sublist("smoother: params").get<std::string>("eigen-analysis: type"), "cg");
    EXPECT_FALSE(m.isSublist("level 0"));
    for (int level = 1; level < 10; ++level) {
      const auto &l = m.sublist("level " + std::to_string(level));
      EXPECT_EQ(l.get<std::string>("smoother: type"), "CHEBYSHEV");
      EXPECT_EQ(l.sublist("smoother: params").get<std::string>("eigen-analysis: type"), "power method");
      EXPECT_EQ(l.sublist("smoother: params").get<int>("chebyshev: eigenvalue max iterations"), 50);
      EXPECT_EQ(l.sublist("smoother: params").get<int>("chebyshev: degree"), 6);
    }
  }
}
