// The run's report without a run: a committed step's record in summary.json, its console line
// (what it calls the linear solves and the volume measure), a refused step's
// inside-out record, how the end is told (converged, or the failure and its reason), a stop
// signal agreed by every rank and written into the summary by the watcher at once (also while
// a step's output holds the output lock), and an output
// file that cannot be written told in summary.json, or on stderr when summary.json cannot be.
#include <gtest/gtest.h>

#include <csignal>
#include <chrono>
#include <fstream>
#include <thread>

#include <Tpetra_Core.hpp>

#include "SharedScratch.hpp"
#include "io/output/OutputError.hpp"
#include "solvers/run/RunReport.hpp"

using namespace glossa;
using namespace glossa::solvers;

namespace {
Teuchos::RCP<const assembly::Map> reportMap() {
  static const auto m = Teuchos::rcp(new assembly::Map(4, 0, Tpetra::getDefaultComm()));
  return m;
}

nlohmann::json readSummary(const std::filesystem::path &dir) {
  std::ifstream in(dir / "summary.json");
  return nlohmann::json::parse(in);
}

StepTrial trialTo(double time, double dt) {
  StepTrial trial(time, dt, 0.5, StepState(reportMap(), 2));
  UzawaResult &r = trial.attempt.uzawa;
  r.newtonIterations = 5;
  r.linearIterations = 40;
  r.solves = 2;
  r.dilatation.max = 3e-4;
  r.dilatation.mean = 1e-4;
  NewtonResult n;
  n.residualNorms = {1.0, 1e-3, 1e-9};
  n.linearIterationsPerStep = {20, 20};
  r.newton = {n};
  trial.attempt.minCornerJ = 0.7;
  trial.attempt.minRegularCornerJ = 0.8;
  return trial;
}

bool root() { return Tpetra::getDefaultComm()->getRank() == 0; }
} // namespace

TEST(RunReport, AStepsRecordCarriesItsSolveStatistics) {
  glossa::testing::SharedScratch dir;
  RunReport report(Tpetra::getDefaultComm(), root(), false);
  report.setDirectory(dir.path());
  report.addStep(trialTo(0.5, 0.25), 0.5, false, 2.0, {{"reactions", nlohmann::json::object()}});
  report.write({2.0, 7, 3, 2, 1});
  if (!root()) return;
  const nlohmann::json summary = readSummary(dir.path());
  ASSERT_EQ(summary["steps"].size(), 1u);
  const nlohmann::json &step = summary["steps"][0];
  EXPECT_EQ(step["time"], 0.5);
  EXPECT_EQ(step["dt"], 0.25);
  EXPECT_EQ(step["newton_iterations"], 5);
  EXPECT_EQ(step["linear_iterations"], 40);
  EXPECT_EQ(step["uzawa_iterations"], 2);
  EXPECT_EQ(step["max_dilatation_error"], 3e-4);
  EXPECT_EQ(step["min_corner_J"], 0.7);
  EXPECT_EQ(step["assembly_seconds"], 1.5); // since the trial began
  EXPECT_FALSE(step.contains("path_stiffness"));  // not measured
  EXPECT_EQ(step["newton_solves"][0]["residual_norms"].size(), 3u);
  EXPECT_TRUE(step.contains("reactions"));
  EXPECT_EQ(summary["residual_evaluations"], 7);
  EXPECT_EQ(summary["tangents_from_residual_pass"], 2);
}

TEST(RunReport, OnAnArcLengthPathTheKrylovCountIsNotClaimed) {
  glossa::testing::SharedScratch dir;
  RunReport report(Tpetra::getDefaultComm(), root(), false);
  report.setDirectory(dir.path());
  report.addStep(trialTo(0.5, 0.25), 0.5, true, 0.0, {});
  EXPECT_FALSE(report.doc()["steps"][0].contains("linear_iterations"));
}

// The step line as printed by the rank that talks, under the solve it describes.
std::string stepLineOf(bool directSolve, bool penalty, bool onPath) {
  RunReport report(Tpetra::getDefaultComm(), root(), true);
  report.describeSolves(directSolve, penalty);
  report.beginSteps(0.0);
  ::testing::internal::CaptureStdout();
  report.stepLine(2, 0.5, 1.0, 0.25, trialTo(0.5, 0.25).attempt.uzawa, onPath, "");
  return ::testing::internal::GetCapturedStdout();
}

TEST(RunReport, TheStepLineNamesWhatItCounts) {
  const std::string iterative = stepLineOf(false, false, false);
  EXPECT_NE(iterative.find("newton 5  krylov 40  uzawa 2  dilatation error 3.0e-04"), std::string::npos) << iterative;
  const std::string direct = stepLineOf(true, false, false);
  EXPECT_NE(direct.find("newton 5  direct solve, 40 Krylov steps on the factors  uzawa 2  dilatation error 3.0e-04"),
            std::string::npos) << direct;
  EXPECT_EQ(direct.find("krylov"), std::string::npos) << direct;
  const std::string penalty = stepLineOf(false, true, false);
  EXPECT_NE(penalty.find("uzawa 2  volume change 3.0e-04"), std::string::npos) << penalty;
  const std::string onPath = stepLineOf(true, true, true);
  EXPECT_NE(onPath.find("newton 5  volume change 3.0e-04"), std::string::npos) << onPath;
  EXPECT_EQ(onPath.find("dilatation error"), std::string::npos) << onPath;
}

TEST(RunReport, ARefusedInsideOutStepIsRecordedWithItsTime) {
  RunReport report(Tpetra::getDefaultComm(), root(), false);
  StepTrial trial = trialTo(0.75, 0.25);
  trial.attempt.why = "inside out";
  trial.attempt.insideOut = {{"condition", "symmetry x"}, {"node", 12}, {"distance", 1e-3}};
  report.stepRefused(trial);
  report.stepRefused(trialTo(0.75, 0.25)); // an ordinary failure adds nothing
  ASSERT_EQ(report.doc()["inside_out_refusals"].size(), 1u);
  EXPECT_EQ(report.doc()["inside_out_refusals"][0]["time"], 0.75);
  EXPECT_EQ(report.doc()["inside_out_refusals"][0]["node"], 12);
}

TEST(RunReport, TheEndSaysWhetherTheRunConvergedAndWhy) {
  glossa::testing::SharedScratch dir;
  {
    RunReport report(Tpetra::getDefaultComm(), root(), false);
    report.setDirectory(dir.path());
    report.finish({}, 1.0, {{"tip", {0.0, 0.0, -1e-3}}});
    EXPECT_TRUE(report.converged());
    if (root()) {
      const nlohmann::json summary = readSummary(dir.path());
      EXPECT_EQ(summary["converged"], true);
      EXPECT_EQ(summary["running"], false);
      EXPECT_EQ(summary["final_time"], 1.0);
      EXPECT_EQ(summary["final_displacement"]["tip"][2], -1e-3);
      EXPECT_FALSE(summary.contains("failure"));
    }
  }
  RunReport report(Tpetra::getDefaultComm(), root(), false);
  report.setDirectory(dir.path());
  report.fail("step to t = 0.5 failed (Newton did not converge) below the minimum step size");
  report.finish({}, 0.25, nlohmann::json::object());
  if (!root()) return;
  const nlohmann::json summary = readSummary(dir.path());
  EXPECT_EQ(summary["converged"], false);
  EXPECT_EQ(summary["final_time"], 0.25);
  EXPECT_EQ(summary["failure"], "step to t = 0.5 failed (Newton did not converge) below the minimum step size");
}

// One test, as a process takes one stop signal: the second within 2 s is the same request.
TEST(RunReport, AStopSignalIsAgreedAndWrittenAtOnceEvenDuringAStepsOutput) {
  glossa::testing::SharedScratch dir;
  RunReport report(Tpetra::getDefaultComm(), root(), false);
  report.setDirectory(dir.path());
  report.addStep(trialTo(0.25, 0.25), 0.25, false, 0.0, {});
  report.write({});
  report.beginSteps(0.25);
  EXPECT_FALSE(report.stopRequested(1, 0.25));
  {
    // A commit's output that outlasts mpiexec's second (a slow disk's syncs): the watcher must
    // not wait for it.
    auto output = report.holdOutput();
    if (root()) std::raise(SIGTERM); // one rank's signal: every rank must stop
    EXPECT_TRUE(report.stopRequested(1, 0.25));
    EXPECT_EQ(report.stoppedBy(), SIGTERM);
    EXPECT_EQ(report.failure().rfind("interrupted by SIGTERM after step 1", 0), 0u) << report.failure();
    if (root()) {
      // The watcher thread marks summary.json while the output still holds its lock.
      nlohmann::json summary;
      for (int k = 0; k < 300; ++k) {
        summary = readSummary(dir.path());
        if (summary.contains("interrupted")) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      EXPECT_EQ(summary["interrupted"], "SIGTERM");
      EXPECT_EQ(summary["running"], false);
      EXPECT_EQ(summary["steps"].size(), 1u);
      EXPECT_EQ(summary["interrupted_while_writing"], true);
      EXPECT_NE(summary["failure"].get<std::string>().find("while the next step was being written"), std::string::npos)
          << summary["failure"];
    }
  }
  // The output's step, once written, says the run was interrupted after it, with no cut.
  report.addStep(trialTo(0.5, 0.25), 0.5, false, 0.0, {});
  report.write({});
  if (!root()) return;
  const nlohmann::json summary = readSummary(dir.path());
  EXPECT_EQ(summary["steps"].size(), 2u);
  EXPECT_EQ(summary["interrupted"], "SIGTERM");
  EXPECT_EQ(summary["running"], false);
  EXPECT_FALSE(summary.contains("interrupted_while_writing"));
  EXPECT_EQ(summary["failure"].get<std::string>().rfind("interrupted by SIGTERM after step 2", 0), 0u) << summary["failure"];
}

TEST(RunReport, AnOutputFileThatCannotBeWrittenEndsTheRunInTheSummary) {
  glossa::testing::SharedScratch dir;
  RunReport report(Tpetra::getDefaultComm(), root(), false);
  report.setDirectory(dir.path());
  report.addStep(trialTo(0.5, 0.25), 0.5, false, 2.0, {{"reactions", nlohmann::json::object()}});
  report.doc()["running"] = true;
  report.write({2.0, 7, 3, 2, 1});
  const std::string what = "cannot write " + (dir.path() / "results_steps/step_000002.h5").string() + ": File too large";
  EXPECT_THROW(report.recordingOutputFailure([&] { throw io::OutputError(what); }), io::OutputError);
  // A filesystem error (a directory that cannot be made) is an output failure too.
  EXPECT_THROW(report.recordingOutputFailure([] {
    throw std::filesystem::filesystem_error("cannot create directory", std::make_error_code(std::errc::no_space_on_device));
  }), std::filesystem::filesystem_error);
  EXPECT_NO_THROW(report.recordingOutputFailure([] {}));
  if (!root()) return;
  const nlohmann::json summary = readSummary(dir.path());
  EXPECT_FALSE(summary["running"].get<bool>());
  EXPECT_FALSE(summary["converged"].get<bool>());
  EXPECT_EQ(summary["steps"].size(), 1u); // what was written before stays
  EXPECT_NE(summary["output_failure"].get<std::string>().find("cannot create directory"), std::string::npos);
}

TEST(RunReport, ASummaryThatCannotBeWrittenEitherIsSaidOnStderr) {
  glossa::testing::SharedScratch dir;
  RunReport report(Tpetra::getDefaultComm(), root(), false);
  report.setDirectory(dir.path());
  // A directory where summary.json should be: its replacement cannot be renamed into place.
  if (root()) std::filesystem::create_directories(dir.path() / "summary.json" / "in_the_way");
  Tpetra::getDefaultComm()->barrier();
  ::testing::internal::CaptureStderr();
  EXPECT_THROW(report.recordingOutputFailure([] { throw io::OutputError("cannot write traces.csv: No space left on device"); }),
               io::OutputError);
  const std::string said = ::testing::internal::GetCapturedStderr();
  if (!root()) {
    EXPECT_EQ(said, ""); // rank 0 speaks for the run
    return;
  }
  EXPECT_NE(said.find("glossa: error: " + (dir.path() / "summary.json").string() + " could not be written either ("),
            std::string::npos) << said;
  EXPECT_TRUE(std::filesystem::is_directory(dir.path() / "summary.json"));
}

