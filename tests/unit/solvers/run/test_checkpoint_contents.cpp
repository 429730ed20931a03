// The contact state's part of a checkpoint (CheckpointContents): the committed multipliers come
// back bit-identical through CBOR, and a restored state evaluates as the one saved: its trial
// multipliers are the committed ones, and no point is taken to be near the obstacle until the
// next evaluation records its gap.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "contact/ContactState.hpp"
#include "solvers/run/CheckpointContents.hpp"

using glossa::contact::ContactPointState;
using glossa::contact::ContactState;

TEST(CheckpointContents, ContactMultipliersSurviveARoundTrip) {
  ContactState state(2);
  // Face 0 pressed: gaps of a penetration, the Uzawa update takes lambda = -eps g (and a value
  // with no short decimal, to see the bits come back), committed.
  const double eps = 1e8;
  state.record(0, {ContactPointState{-1e-5 / 3, 1e3 / 3}, {-2e-5, 2e3}, {0.0, 0.0}, {1e-3, 0.0}});
  state.updateMultipliers(eps);
  state.commit();
  // A trial update after the commit is not what the checkpoint keeps.
  state.record(0, {ContactPointState{-1.0, 1.0}, {-1.0, 1.0}, {-1.0, 1.0}, {-1.0, 1.0}});
  state.updateMultipliers(eps);

  const std::vector<std::uint8_t> bytes = nlohmann::json::to_cbor(glossa::solvers::toJson(state.snapshot()));
  ContactState restored(2);
  restored.restore(glossa::solvers::contactSnapshotFromJson(nlohmann::json::from_cbor(bytes)));

  const auto lambda = restored.trialMultipliers(0);
  EXPECT_EQ(lambda[0], eps * (1e-5 / 3));
  EXPECT_EQ(lambda[1], eps * 2e-5);
  EXPECT_EQ(lambda[2], 0.0);
  EXPECT_EQ(lambda[3], 0.0);
  EXPECT_EQ(restored.committedMultipliers(0), state.committedMultipliers(0));
  for (std::size_t q = 0; q < 4; ++q) {
    EXPECT_EQ(restored.trialMultipliers(1)[q], 0.0);
    EXPECT_TRUE(std::isinf(restored.point(0, q).gap));
    EXPECT_EQ(restored.point(0, q).pressure, 0.0);
  }
  EXPECT_EQ(restored.largestGapError(), 0.0);
}

// The friction anchors and slips come back bit-identical, and a point without an anchor (NaN,
// which JSON cannot hold) comes back without one.
TEST(CheckpointContents, ContactAnchorsSurviveARoundTrip) {
  ContactState state(1);
  glossa::contact::FaceContactPoints points{};
  points[0].anchor = Eigen::Vector3d(1.0 / 3, -2e-3, 0.7);
  points[0].slip = 1e-4 / 3;
  points[2].anchor = Eigen::Vector3d(0.0, 0.0, 0.0);
  state.record(0, points);
  state.commit();
  const std::vector<std::uint8_t> bytes = nlohmann::json::to_cbor(glossa::solvers::toJson(state.snapshot()));
  ContactState restored(1);
  restored.restore(glossa::solvers::contactSnapshotFromJson(nlohmann::json::from_cbor(bytes)));
  const auto anchors = restored.committedAnchors(0);
  EXPECT_EQ(anchors[0], points[0].anchor);
  EXPECT_EQ(anchors[2], Eigen::Vector3d::Zero());
  EXPECT_FALSE(anchors[1].allFinite());
  EXPECT_FALSE(anchors[3].allFinite());
  EXPECT_EQ(restored.snapshot().slip, state.snapshot().slip);
}
