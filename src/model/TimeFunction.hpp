#pragma once
// A scalar function of time that scales a load or a prescribed displacement, or gives a muscle
// group's neural input: constant, a linear ramp from 0 to 1 over a duration (deal.II step-44
// ramps its pressure over the whole run), a piecewise-linear table, or piecewise-constant steps
// (an input switched on and off), or the breathing profile of eq. 27 (loads/PressureField.hpp).

#include <string>
#include <vector>

#include "loads/PressureField.hpp"

namespace glossa::model {

class TimeFunction {
public:
  enum class Kind { Constant, Ramp, Table, Steps, Breathing };

  static TimeFunction constant() { return TimeFunction(Kind::Constant, 0.0, {}, {}); }
  static TimeFunction ramp(double duration) { return TimeFunction(Kind::Ramp, duration, {}, {}); }
  static TimeFunction table(std::vector<double> times, std::vector<double> values);
  // values[i] from times[i] until times[i+1]; values[0] before times[0].
  static TimeFunction steps(std::vector<double> times, std::vector<double> values);
  static TimeFunction breathing(loads::BreathingProfile profile);

  double operator()(double t) const { return scale_ * shape(t); }
  // The same function times `factor`.
  TimeFunction scaled(double factor) const {
    TimeFunction f = *this;
    f.scale_ *= factor;
    return f;
  }

private:
  TimeFunction(Kind kind, double duration, std::vector<double> times, std::vector<double> values)
      : kind_(kind), duration_(duration), times_(std::move(times)), values_(std::move(values)) {}

  double shape(double t) const;

  Kind kind_;
  double scale_ = 1.0;
  double duration_;
  std::vector<double> times_, values_;
  loads::BreathingProfile breathing_;
};

} // namespace glossa::model
