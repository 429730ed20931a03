// A checkpoint's values against what a run could have written (CheckpointSanity): a valid state
// passes, and each value a hand edit or a forged CRC could put there is refused, naming the value
// and what is allowed: a time outside [0, end time] (NaN, 1e300, negative), a step size that is
// not finite or lies outside the deck's minimum and step size, negative counts, non-finite
// fields, sizes of another mesh, wrong types, missing keys, CSV lengths the files no longer have,
// and times that disagree between the run part, the summary and the muscle history.
#include <cmath>
#include <fstream>
#include <limits>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/output/CheckpointError.hpp"
#include "io/output/ScratchDirectory.hpp"
#include "solvers/run/CheckpointSanity.hpp"

using glossa::io::CheckpointError;
using glossa::solvers::CheckpointShape;
using nlohmann::json;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

class CheckpointSanity : public ::testing::Test {
protected:
  void SetUp() override {
    shape.step = 2;
    shape.endTime = 1.0;
    shape.nominalStep = 0.25;
    shape.minimumStep = 1e-3;
    shape.displacements = 3;
    shape.elements = 2;
    shape.tissues = 1;
    shape.groups = 1;
    shape.lambdaC = 2;
    shape.externalLambdaC = {1};
    shape.outputDirectory = dir.path();
    std::ofstream(dir / "traces.csv") << std::string(100, 'x');
  }

  // The message of the refusal of `run` and `part`, "" if they pass.
  std::string refusal() const {
    try {
      glossa::solvers::checkRunValues(run, shape);
      glossa::solvers::checkPartValues(part, run.at("time").get<double>(), shape);
    } catch (const CheckpointError &e) {
      return e.what();
    }
    return "";
  }

  glossa::io::testing::ScratchDirectory dir;
  CheckpointShape shape;
  // A run after its second step of 0.25 s, with one tissue, one muscle group and one external muscle.
  json run = {{"deck", "Time/end time = 1\n"},
              {"ranks", 1},
              {"control_groups", 1},
              {"step", 2},
              {"time", 0.5},
              {"previous_dt", 0.25},
              {"step_size", {0.25, 2}},
              {"penalty_ratios", json::array({30.0})},
              {"softening_said", false},
              {"limit_point", {{"reference", 1.0}, {"last", 0.9}}},
              {"outputs",
               {{"csv_bytes", {{"traces.csv", 100}}},
                {"field_steps", {{{"time", 0.0}, {"attributes", json::array()}}, {{"time", 0.5}, {"attributes", json::array()}}}}}},
              {"summary", {{"steps", {{{"time", 0.25}}, {{"time", 0.5}}}}}}};
  json part = {{"u", {0.0, 1e-3, -2e-3}},
               {"lambda", {1.5, -0.5}},
               {"multiplier_prediction", {{"last", json::array()}, {"before_last", json::array()}, {"last_dt", 0.0}}},
               {"muscle",
                {{"lambda_c", {1.0, 0.98}},
                 {"alpha", json::array({0.3})},
                 {"input", json::array({1.0})},
                 {"external_lambda_c", json::array({json::array({1.01})})},
                 {"time", 0.5},
                 {"dt", 0.25}}}};
};

#define EXPECT_REFUSED(text) \
  do { \
    const std::string why = refusal(); \
    EXPECT_NE(why.find(text), std::string::npos) << "expected '" << (text) << "' in: '" << why << "'"; \
  } while (0)

TEST_F(CheckpointSanity, AStateARunWritesPasses) {
  EXPECT_EQ(refusal(), "");
  // The last step may end one unit past the end time (t + (end - t) rounded).
  shape.endTime = std::nextafter(0.5, 0.0);
  EXPECT_EQ(refusal(), "");
}

TEST_F(CheckpointSanity, ATimeOutsideZeroToTheEndTimeIsRefused) {
  run["time"] = kNaN;
  EXPECT_REFUSED("time = nan; it must be finite and in [0, 1] (Time/end time)");
  run["time"] = 1e300;
  EXPECT_REFUSED("time = 1e+300; it must be finite and in [0, 1]");
  run["time"] = -0.25;
  EXPECT_REFUSED("time = -0.25");
  run["time"] = std::numeric_limits<double>::infinity();
  EXPECT_REFUSED("time = inf");
}

TEST_F(CheckpointSanity, AStepSizeNotFiniteAndPositiveOrAboveTheDecksIsRefused) {
  for (const double dt : {-0.25, 0.0, kNaN, 0.5, 5e-4, 4.9e-324}) {
    run["step_size"][0] = dt;
    EXPECT_REFUSED("the step size = ");
    EXPECT_REFUSED("it must be finite and in [0.001, 0.25] (Time/minimum step size to Time/step size)");
  }
  shape.minimumStep = 0.0;
  run["step_size"][0] = 0.0;
  EXPECT_REFUSED("the step size = 0; it must be finite and in (0, 0.25]");
  run["step_size"][0] = 0.125;
  EXPECT_EQ(refusal(), "");
  run["previous_dt"] = 0.75; // longer than the 0.5 s run so far
  EXPECT_REFUSED("previous_dt = 0.75; it must be finite and in [0, 0.5]");
}

TEST_F(CheckpointSanity, NegativeCountsAndAnotherStepAreRefused) {
  run["step_size"][1] = -1;
  EXPECT_REFUSED("the step size's successes = -1; it must be a whole number in [0, 2147483647]");
  run["step_size"][1] = 0;
  run["ranks"] = -2;
  EXPECT_REFUSED("run/ranks = -2");
  run["ranks"] = 1;
  run["step"] = 3;
  EXPECT_REFUSED("step = 3, and the checkpoint is named after step 2");
  run["step"] = 2.5;
  EXPECT_REFUSED("step = 2.5; it must be a whole number");
}

TEST_F(CheckpointSanity, NonFiniteOrImpossibleFieldValuesAreRefused) {
  part["u"][1] = kNaN;
  EXPECT_REFUSED("u (displacement)[1] = nan");
  part["u"][1] = 0.0;
  part["lambda"][0] = -std::numeric_limits<double>::infinity();
  EXPECT_REFUSED("lambda (multipliers)[0] = -inf");
  part["lambda"][0] = 0.0;
  part["muscle"]["alpha"][0] = 1.5;
  EXPECT_REFUSED("muscle/alpha[0] = 1.5; it must be finite and in [0, 1] (an activation)");
  part["muscle"]["alpha"][0] = 0.5;
  part["muscle"]["lambda_c"][1] = 0.0;
  EXPECT_REFUSED("muscle/lambda_c is 0");
  part["muscle"]["lambda_c"][1] = 1.0;
  run["penalty_ratios"][0] = -30.0;
  EXPECT_REFUSED("penalty_ratios[0] = -30");
}

TEST_F(CheckpointSanity, SizesOfAnotherMeshOrPartitionAreRefused) {
  part["u"] = {0.0, 1.0};
  EXPECT_REFUSED("u (displacement) has 2 values, this run has 3 here (another mesh or partition)");
  part["u"] = {0.0, 1.0, 2.0};
  part["muscle"]["external_lambda_c"] = json::array();
  EXPECT_REFUSED("muscle/external_lambda_c is not one array per external muscle (1)");
  part["muscle"]["external_lambda_c"] = json::array({json::array({1.0})});
  part["multiplier_prediction"]["last"] = {1.0, 2.0, 3.0};
  EXPECT_REFUSED("multiplier_prediction/last has 3 values, this run has 2");
}

TEST_F(CheckpointSanity, WrongTypesAndMissingValuesAreRefused) {
  run["time"] = "0.5";
  EXPECT_REFUSED("time is string, not a number");
  run["time"] = 0.5;
  part.erase("u");
  EXPECT_REFUSED("part has no 'u'");
  part["u"] = {0.0, 0.0, 0.0};
  run["summary"] = json::array();
  EXPECT_REFUSED("summary is array, not an object");
}

TEST_F(CheckpointSanity, OutputLengthsTheFilesNoLongerHaveAreRefused) {
  run["outputs"]["csv_bytes"]["traces.csv"] = 101;
  EXPECT_REFUSED("it records traces.csv at 101 bytes, and " + (dir / "traces.csv").string() + " is only 100 bytes long");
  run["outputs"]["csv_bytes"] = {{"reactions.csv", 0}};
  EXPECT_REFUSED((dir / "reactions.csv").string() + " is missing");
  run["outputs"]["csv_bytes"] = {{"../traces.csv", 0}};
  EXPECT_REFUSED("names '../traces.csv', not a file of the output directory");
  run["outputs"]["csv_bytes"] = {{"traces.csv", 100}};
  run["outputs"]["field_steps"][1]["time"] = 0.75;
  EXPECT_REFUSED("outputs/field_steps[1]/time = 0.75");
}

TEST_F(CheckpointSanity, TimesThatDisagreeAcrossTheCheckpointAreRefused) {
  // A plausible time edited in one place only: the summary and the muscle history still say 0.5 s.
  run["time"] = 0.75;
  run["outputs"]["field_steps"][1]["time"] = 0.5;
  EXPECT_REFUSED("summary/steps' last time is 0.5 s, the checkpoint's time 0.75 s");
  run["time"] = 0.5;
  part["muscle"]["time"] = 0.25;
  EXPECT_REFUSED("muscle/time is 0.25 s, the checkpoint's time 0.5 s");
  part["muscle"]["time"] = 0.5;
  run["summary"]["steps"].push_back({{"time", 0.5}});
  EXPECT_REFUSED("summary/steps lists 3 steps, the checkpoint is after step 2");
}

// The contacts' multipliers: one entry per contact, 4 per contact face, each a contact pressure
// (finite, >= 0); with them the friction anchors (3 coordinates per point), whether each point
// has one (0 or 1) and the slips (>= 0).
TEST_F(CheckpointSanity, ContactMultipliersOfAnotherMeshOrNegativeAreRefused) {
  shape.contactPoints = {8};
  EXPECT_REFUSED("part has no 'contact'");
  part["contact"] = json::array({{{"multipliers", {0.0, 0.0, 1e3, 1e3, 0.0, 0.0, 1e3, 1e3}},
                                  {"anchors", std::vector<double>(24, 0.5)},
                                  {"anchored", {0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 1.0}},
                                  {"slip", std::vector<double>(8, 1e-3)}}});
  EXPECT_EQ(refusal(), "");
  part["contact"][0]["slip"][1] = -1.0;
  EXPECT_REFUSED("contact[0]/slip[1] = -1; it must be finite and in [0, inf] (a slip length)");
  part["contact"][0]["slip"][1] = 0.0;
  part["contact"][0]["anchored"][3] = 2.0;
  EXPECT_REFUSED("contact[0]/anchored[3] = 2");
  part["contact"][0]["anchored"][3] = 1.0;
  part["contact"][0]["anchors"] = std::vector<double>(8, 0.5);
  EXPECT_REFUSED("contact[0]/anchors has 8 values, this run has 24 here");
  part["contact"][0]["anchors"] = std::vector<double>(24, 0.5);
  part["contact"][0]["multipliers"][2] = -1.0;
  EXPECT_REFUSED("contact[0]/multipliers[2] = -1; it must be finite and in [0, inf] (a contact pressure)");
  part["contact"][0]["multipliers"][2] = kNaN;
  EXPECT_REFUSED("contact[0]/multipliers[2] = nan");
  part["contact"][0]["multipliers"] = {0.0, 0.0, 1e3, 1e3};
  EXPECT_REFUSED("contact[0]/multipliers has 4 values, this run has 8 here");
  part["contact"] = json::array();
  EXPECT_REFUSED("contact is not one entry per contact (1)");
}

}  // namespace
