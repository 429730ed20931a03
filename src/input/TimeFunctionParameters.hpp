#pragma once
// The deck's "time function" sublist (of a load, a boundary condition, a muscle group's input):
// its parameters, and the model::TimeFunction they describe.

#include <string>

#include <Teuchos_ParameterList.hpp>

#include "model/TimeFunction.hpp"

namespace glossa::input {

Teuchos::ParameterList timeFunctionParameters(const std::string &defaultType = "ramp");
// `endTime` is the run's end time, the default ramp duration.
model::TimeFunction parseTimeFunction(const Teuchos::ParameterList &list, double endTime);

} // namespace glossa::input
