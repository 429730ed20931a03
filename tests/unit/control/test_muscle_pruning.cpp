// Muscle pruning: the fibre length measure on hand-built elements, the length-weighted average
// stretch per group on a hand-built stretch state, and the tension rule.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

#include "control/MusclePruning.hpp"

namespace glossa::control {
namespace {

using HexNodes = Eigen::Matrix<double, 8, 3>;

HexNodes unitCube() {
  HexNodes X;
  X << 0, 0, 0,  //
      1, 0, 0,   //
      1, 1, 0,   //
      0, 1, 0,   //
      0, 0, 1,   //
      1, 0, 1,   //
      1, 1, 1,   //
      0, 1, 1;
  return X;
}

TEST(MusclePruning, FibreLengthMeasureIsTheExtentAlongTheFibre) {
  const HexNodes X = unitCube();
  EXPECT_DOUBLE_EQ(fibreLengthMeasure(X, Eigen::Vector3d::UnitX()), 1.0);
  EXPECT_DOUBLE_EQ(fibreLengthMeasure(X, Eigen::Vector3d(0, -3, 0)),
                   1.0);  // sign and length of N do not matter
  // Along a face diagonal: the projections of the corners span sqrt(2).
  EXPECT_NEAR(fibreLengthMeasure(X, Eigen::Vector3d(1, 1, 0)), std::sqrt(2.0), 1e-15);
  // Along the body diagonal: sqrt(3).
  EXPECT_NEAR(fibreLengthMeasure(X, Eigen::Vector3d(1, 1, 1)), std::sqrt(3.0), 1e-15);
  // A 2 x 0.5 x 1 box, rotated and translated, along its rotated long edge: 2.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, -1).normalized()).toRotationMatrix();
  const Eigen::Matrix3d D = Eigen::Vector3d(2.0, 0.5, 1.0).asDiagonal();
  const HexNodes Y = ((X * D * R.transpose()).rowwise() + Eigen::RowVector3d(3, -1, 2)).eval();
  EXPECT_NEAR(fibreLengthMeasure(Y, R.col(0)), 2.0, 1e-14);
  EXPECT_NEAR(fibreLengthMeasure(Y, R.col(1)), 0.5, 1e-14);
  EXPECT_THROW(fibreLengthMeasure(X, Eigen::Vector3d::Zero()), std::invalid_argument);
}

// Four groups: group 0 stretched on the whole, group 1 barely, group 2 compressed, group 3
// without fibres; passive fibres (group -1) do not count.
GroupStretchSums handState() {
  GroupStretchSums s(4);
  s.add(0, 1.10, 2.0);
  s.add(0, 1.00, 1.0);
  s.add(0, 0.94, 1.0);
  s.add(1, 0.98, 1.0);
  s.add(1, 1.01, 3.0);
  s.add(2, 0.90, 0.5);
  s.add(-1, 5.0, 10.0);
  return s;
}

TEST(MusclePruning, LengthWeightedAverageStretch) {
  const std::vector<double> lambdaBar = handState().average();
  ASSERT_EQ(lambdaBar.size(), 4u);
  EXPECT_NEAR(lambdaBar[0], (1.10 * 2 + 1.00 + 0.94) / 4.0, 1e-15);  // 1.035
  EXPECT_NEAR(lambdaBar[1], (0.98 + 1.01 * 3) / 4.0, 1e-15);         // 1.0025
  EXPECT_NEAR(lambdaBar[2], 0.90, 1e-15);
  EXPECT_TRUE(std::isnan(lambdaBar[3]));
}

TEST(MusclePruning, SumsOverRanksAddUp) {
  GroupStretchSums rank0(4), rank1(4);
  rank0.add(0, 1.10, 2.0);
  rank0.add(1, 0.98, 1.0);
  rank0.add(2, 0.90, 0.5);
  rank1.add(0, 1.00, 1.0);
  rank1.add(0, 0.94, 1.0);
  rank1.add(1, 1.01, 3.0);
  rank0 += rank1;
  const std::vector<double> merged = rank0.average(), whole = handState().average();
  for (int m = 0; m < 3; ++m) EXPECT_NEAR(merged[m], whole[m], 1e-15);
  EXPECT_THROW(rank0 += GroupStretchSums(3), std::invalid_argument);
}

TEST(MusclePruning, GroupsInTension) {
  const std::vector<double> lambdaBar = handState().average();
  const std::vector<double> one(4, 1.0);
  const std::vector<bool> none(4, false);
  // 1.035 > 1.005; 1.0025 is not; 0.9 is not; group 3 has no fibres and is kept.
  EXPECT_EQ(groupsInTension(lambdaBar, one, 0.005, none), (std::vector<int>{0, 3}));
  // Without tolerance group 1's small stretch counts.
  EXPECT_EQ(groupsInTension(lambdaBar, one, 0.0, none), (std::vector<int>{0, 1, 3}));
  // A group marked always evaluated (the genioglossus) stays in even when compressed.
  EXPECT_EQ(groupsInTension(lambdaBar, one, 0.005, {false, false, true, false}), (std::vector<int>{0, 2, 3}));
  // Against a pre-strained reference: group 0 at 1.035 is below its reference 1.04.
  EXPECT_EQ(groupsInTension(lambdaBar, {1.04, 0.95, 0.95, 1.0}, 0.0, none), (std::vector<int>{1, 3}));
  // At the reference state exactly nothing is in tension.
  EXPECT_TRUE(groupsInTension({1.0, 1.0}, {1.0, 1.0}, 0.0, {false, false}).empty());
  EXPECT_THROW(groupsInTension(lambdaBar, {1.0, 1.0}, 0.0, none), std::invalid_argument);
  EXPECT_THROW(groupsInTension(lambdaBar, one, -0.1, none), std::invalid_argument);
}

TEST(MusclePruning, GenomeToInputsAndBack) {
  const std::vector<int> evaluated = {0, 2, 3};
  const std::vector<double> u = inputsFromGenome(evaluated, {1.0, 0.25, 0.5}, 5);
  EXPECT_EQ(u, (std::vector<double>{1.0, 0.0, 0.25, 0.5, 0.0}));
  EXPECT_EQ(genomeFromInputs(evaluated, u), (Genome{1.0, 0.25, 0.5}));
  // The previous step's inputs restricted to this step's groups.
  EXPECT_EQ(genomeFromInputs({1, 2}, u), (Genome{0.0, 0.25}));
  EXPECT_THROW(inputsFromGenome(evaluated, {1.0}, 5), std::invalid_argument);
  EXPECT_THROW(inputsFromGenome({0, 7}, {1.0, 1.0}, 5), std::invalid_argument);
  EXPECT_THROW(genomeFromInputs({5}, u), std::invalid_argument);
}

TEST(MusclePruning, RejectsBadContributions) {
  GroupStretchSums s(2);
  EXPECT_THROW(s.add(2, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(s.add(-2, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(s.add(0, 0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(s.add(0, 1.0, -1.0), std::invalid_argument);
  EXPECT_THROW(s.add(0, std::nan(""), 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace glossa::control
