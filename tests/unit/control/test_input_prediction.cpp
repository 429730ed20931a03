// The linear prediction of a control step's inputs (InputPrediction.hpp) against hand values.
#include <gtest/gtest.h>

#include <stdexcept>

#include "control/InputPrediction.hpp"

using glossa::control::GeneType;
using glossa::control::linearPrediction;

TEST(InputPrediction, ExtrapolatesLinearlyAndClipsToTheUnitInterval) {
  // 2 u1 - u0: rising 0.2 -> 0.3 gives 0.4; falling 0.5 -> 0.2 gives -0.1, clipped to 0; rising
  // 0.7 -> 0.9 gives 1.1, clipped to 1; steady stays.
  const auto u = linearPrediction({0.3, 0.2, 0.9, 0.6}, {0.2, 0.5, 0.7, 0.6}, GeneType::continuous);
  ASSERT_EQ(u.size(), 4u);
  EXPECT_NEAR(u[0], 0.4, 1e-15);
  EXPECT_EQ(u[1], 0.0);
  EXPECT_EQ(u[2], 1.0);
  EXPECT_NEAR(u[3], 0.6, 1e-15);
}

TEST(InputPrediction, BinaryGenesAreRounded) {
  // 1 after 0 predicts 2 (-> 1); 0 after 1 predicts -1 (-> 0); steady values stay.
  EXPECT_EQ(linearPrediction({1, 0, 1, 0}, {0, 1, 1, 0}, GeneType::binary), (std::vector<double>{1, 0, 1, 0}));
}

TEST(InputPrediction, RefusesMismatchedOrOutOfRangeInputs) {
  EXPECT_THROW(linearPrediction({0.1, 0.2}, {0.1}, GeneType::continuous), std::invalid_argument);
  EXPECT_THROW(linearPrediction({1.5}, {0.1}, GeneType::continuous), std::invalid_argument);
  EXPECT_THROW(linearPrediction({0.5}, {-0.1}, GeneType::continuous), std::invalid_argument);
}
