#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "contact/ContactState.hpp"

using glossa::contact::ContactState;
using glossa::contact::FaceContactPoints;

namespace {
// Gap and pressure per point: an active point 2 mm in, an active one held 1 mm clear by its
// multiplier, an inactive one 5 mm clear, one beyond the search radius.
FaceContactPoints samplePoints() { return {{{-2e-3, 40.0}, {1e-3, 7.0}, {5e-3, 0.0}, {std::numeric_limits<double>::infinity(), 0.0}}}; }
}  // namespace

// A new state has no multipliers, and every point unknown (infinitely far, no pressure).
TEST(ContactState, StartsWithoutMultipliersOrContact) {
  const ContactState state(3);
  EXPECT_EQ(state.faces(), 3u);
  EXPECT_EQ(state.trialMultipliers(2), (glossa::contact::FaceMultipliers{0, 0, 0, 0}));
  EXPECT_EQ(state.point(1, 3).gap, std::numeric_limits<double>::infinity());
  EXPECT_EQ(state.largestGapError(), 0.0);
}

// The Uzawa update at the recorded gaps, lambda <- max(0, lambda - eps g) with eps = 1e4:
// 0 + 20 = 20, 0 - 10 -> 0, and 0 for the far points; the gap error is the largest |g| of the
// active points (2 mm), the penetration the largest -g (2 mm).
TEST(ContactState, UzawaUpdateAtTheRecordedGaps) {
  ContactState state(2);
  state.record(1, samplePoints());
  EXPECT_DOUBLE_EQ(state.largestGapError(), 2e-3);
  EXPECT_DOUBLE_EQ(state.largestPenetration(), 2e-3);
  state.updateMultipliers(1.0e4);
  EXPECT_EQ(state.trialMultipliers(1), (glossa::contact::FaceMultipliers{20.0, 0.0, 0.0, 0.0}));
  EXPECT_EQ(state.trialMultipliers(0), (glossa::contact::FaceMultipliers{0, 0, 0, 0}));
  EXPECT_EQ(state.committedMultipliers(1), (glossa::contact::FaceMultipliers{0, 0, 0, 0}));
}

// Commit keeps the trial multipliers; roll back returns to the committed ones.
TEST(ContactState, CommitAndRollBack) {
  ContactState state(1);
  state.record(0, samplePoints());
  state.updateMultipliers(1.0e4);
  state.commit();
  EXPECT_DOUBLE_EQ(state.committedMultipliers(0)[0], 20.0);
  state.updateMultipliers(1.0e4);  // the same gaps again: 20 + 20
  EXPECT_DOUBLE_EQ(state.trialMultipliers(0)[0], 40.0);
  state.rollBack();
  EXPECT_DOUBLE_EQ(state.trialMultipliers(0)[0], 20.0);
}

// A snapshot restores to an equal state (trial = committed); mismatched sizes are refused.
TEST(ContactState, SnapshotRestoresTheCommittedState) {
  ContactState state(2);
  state.record(0, samplePoints());
  state.updateMultipliers(1.0e4);
  state.commit();
  ContactState restored;
  restored.restore(state.snapshot());
  EXPECT_EQ(restored.faces(), 2u);
  EXPECT_EQ(restored.trialMultipliers(0), state.committedMultipliers(0));
  EXPECT_EQ(restored.point(0, 1).gap, 1e-3);
  EXPECT_EQ(restored.point(0, 0).pressure, 40.0);
  ContactState::Snapshot bad = state.snapshot();
  bad.gap.pop_back();
  EXPECT_THROW(restored.restore(bad), std::invalid_argument);
  bad = state.snapshot();
  for (auto *v : {&bad.multipliers, &bad.gap, &bad.pressure}) v->push_back(0.0);
  EXPECT_THROW(restored.restore(bad), std::invalid_argument);
}

// A deformable pair's slave faces carry n x n points each: the Uzawa update, the gap error and
// the snapshot work per point, and the four-multiplier view of a rigid contact's face is refused.
TEST(ContactState, NinePointsPerFace) {
  ContactState state(2, 9);
  EXPECT_EQ(state.pointsPerFace(), 9u);
  EXPECT_EQ(state.faces(), 2u);
  state.record(1, 8, {-2e-3, 20.0, 0.1}); // pressed in by 2 mm, carrying 20 Pa
  state.record(0, 3, {1e-3, 0.0, 0.1});   // apart
  state.updateMultipliers(1.0e4);
  EXPECT_DOUBLE_EQ(state.trialMultiplier(1, 8), 20.0);
  EXPECT_DOUBLE_EQ(state.trialMultiplier(0, 3), 0.0);
  EXPECT_DOUBLE_EQ(state.largestGapError(), 2e-3);
  EXPECT_THROW(state.trialMultipliers(0), std::logic_error);
  state.commit();
  ContactState restored(2, 9);
  restored.restore(state.snapshot());
  EXPECT_DOUBLE_EQ(restored.trialMultiplier(1, 8), 20.0);
  ContactState::Snapshot bad = state.snapshot();
  for (auto *v : {&bad.multipliers, &bad.gap, &bad.pressure}) v->resize(16, 0.0); // 4 per face: not 9
  EXPECT_THROW(restored.restore(bad), std::invalid_argument);
  EXPECT_THROW(ContactState(1, 0), std::invalid_argument);
}

// Friction history: a record writes the trial anchors and adds each point's slip to the committed
// total; commit keeps them, roll back returns to them; a snapshot carries them (NaN: no anchor).
// A tied point is active but has no gap error (the penalty alone holds it).
TEST(ContactState, AnchorsAndSlipAreCommittedAndRolledBack) {
  ContactState state(1);
  FaceContactPoints points = samplePoints();
  points[0].anchor = Eigen::Vector3d(1, 2, 3);
  points[0].slip = 0.25;
  points[1].tied = true;
  state.record(0, points);
  EXPECT_TRUE(state.point(0, 1).active());
  EXPECT_DOUBLE_EQ(state.largestGapError(), 2e-3);  // point 1 (1 mm clear) is tied: not tested
  EXPECT_FALSE(state.committedAnchors(0)[0].allFinite());
  state.commit();
  EXPECT_EQ(state.committedAnchors(0)[0], Eigen::Vector3d(1, 2, 3));
  EXPECT_FALSE(state.committedAnchors(0)[2].allFinite());
  state.record(0, points);  // another 0.25 in the next step
  EXPECT_DOUBLE_EQ(state.point(0, 0).slip, 0.5);
  state.rollBack();
  state.record(0, samplePoints());  // no slip this time: the committed total
  EXPECT_DOUBLE_EQ(state.point(0, 0).slip, 0.25);
  ContactState restored;
  restored.restore(state.snapshot());
  EXPECT_EQ(restored.committedAnchors(0)[0], Eigen::Vector3d(1, 2, 3));
  EXPECT_FALSE(restored.committedAnchors(0)[1].allFinite());
  ContactState::Snapshot bad = state.snapshot();
  bad.anchors.pop_back();
  EXPECT_THROW(restored.restore(bad), std::invalid_argument);
}
