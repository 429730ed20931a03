#pragma once
// The prediction of a control step's neural inputs from the two steps before it (paper §6.1:
// generation 0 holds "a prediction for the solution based on previous steps"):
//
//   u_k = clip(2 u_{k-1} - u_{k-2}, 0, 1)   per group,
//
// linear extrapolation in time at a constant step, so a search under a rising or falling load
// (a breath) starts where the inputs are heading rather than where they were. Binary genes are
// rounded to 0 or 1 (a half rounds up).

#include <vector>

#include "control/GeneticAlgorithmParameters.hpp"

namespace glossa::control {

// previous = u_{k-1}, older = u_{k-2}, one input per group each. Throws std::invalid_argument
// for sizes that differ or an input outside [0, 1].
std::vector<double> linearPrediction(const std::vector<double> &previous, const std::vector<double> &older,
                                     GeneType geneType);

} // namespace glossa::control
