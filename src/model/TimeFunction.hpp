#pragma once
// A scalar function of time that scales a load or a prescribed displacement: constant, a linear
// ramp from 0 to 1 over a duration (deal.II step-44 ramps its pressure over the whole run), or a
// piecewise-linear table.

#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

namespace glossa::model {

class TimeFunction {
public:
  enum class Kind { Constant, Ramp, Table };

  static TimeFunction constant() { return TimeFunction(Kind::Constant, 0.0, {}, {}); }
  static TimeFunction ramp(double duration) { return TimeFunction(Kind::Ramp, duration, {}, {}); }
  static TimeFunction table(std::vector<double> times, std::vector<double> values);

  // The parameters of a "time function" sublist, and the function they describe.
  static Teuchos::ParameterList validParameters();
  // `endTime` is the run's end time, the default ramp duration.
  static TimeFunction fromParameters(const Teuchos::ParameterList &list, double endTime);

  double operator()(double t) const;

private:
  TimeFunction(Kind kind, double duration, std::vector<double> times, std::vector<double> values)
      : kind_(kind), duration_(duration), times_(std::move(times)), values_(std::move(values)) {}

  Kind kind_;
  double duration_;
  std::vector<double> times_, values_;
};

} // namespace glossa::model
