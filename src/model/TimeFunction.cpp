#include "model/TimeFunction.hpp"

#include <algorithm>
#include <stdexcept>

namespace glossa::model {

TimeFunction TimeFunction::table(std::vector<double> times, std::vector<double> values) {
  if (times.size() != values.size() || times.empty())
    throw std::invalid_argument("time function table: 'times' and 'values' must have the same, "
                                "non-zero length");
  if (!std::is_sorted(times.begin(), times.end()) ||
      std::adjacent_find(times.begin(), times.end()) != times.end())
    throw std::invalid_argument("time function table: 'times' must increase strictly");
  return TimeFunction(Kind::Table, 0.0, std::move(times), std::move(values));
}

TimeFunction TimeFunction::breathing(loads::BreathingProfile profile) {
  profile.validate();
  TimeFunction f(Kind::Breathing, 0.0, {}, {});
  f.breathing_ = profile;
  return f;
}

TimeFunction TimeFunction::steps(std::vector<double> times, std::vector<double> values) {
  TimeFunction f = table(std::move(times), std::move(values));
  f.kind_ = Kind::Steps;
  return f;
}

double TimeFunction::shape(double t) const {
  switch (kind_) {
  case Kind::Constant: return 1.0;
  case Kind::Ramp: return std::clamp(t / duration_, 0.0, 1.0);
  case Kind::Table: {
    if (t <= times_.front()) return values_.front();
    if (t >= times_.back()) return values_.back();
    const auto hi = std::upper_bound(times_.begin(), times_.end(), t);
    const std::size_t i = static_cast<std::size_t>(hi - times_.begin());
    const double s = (t - times_[i - 1]) / (times_[i] - times_[i - 1]);
    return (1 - s) * values_[i - 1] + s * values_[i];
  }
  case Kind::Breathing: return breathing_(t);
  case Kind::Steps: {
    const auto hi = std::upper_bound(times_.begin(), times_.end(), t);
    return hi == times_.begin() ? values_.front() : values_[static_cast<std::size_t>(hi - times_.begin()) - 1];
  }
  }
  return 1.0;
}

} // namespace glossa::model
