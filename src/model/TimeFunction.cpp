#include "model/TimeFunction.hpp"

#include <algorithm>
#include <stdexcept>

#include "io/deck/ParameterSpec.hpp"

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

Teuchos::ParameterList TimeFunction::validParameters(const std::string &defaultType) {
  Teuchos::ParameterList p("time function");
  io::declareString(p, "type", defaultType,
                    "constant: 1 at all times; ramp: t/duration up to 1; table: piecewise linear "
                    "in 'times'/'values', constant beyond the ends; steps: values[i] from times[i] "
                    "to the next time (values[0] before the first); breathing: eq. 27, "
                    "sin(2 pi (t - start) / period)^exponent, rectified (doc/loads.md)",
                    {"constant", "ramp", "table", "steps", "breathing"});
  io::declareDouble(p, "ramp duration", 0.0, "s",
                    "time over which a ramp rises from 0 to 1; 0 means the run's end time",
                    io::Range::nonNegative());
  io::declareDoubleArray(p, "times", Teuchos::Array<double>(), "s", "table abscissae (increasing)", 0);
  io::declareDoubleArray(p, "values", Teuchos::Array<double>(), "", "table values", 0);
  io::declareDouble(p, "breathing period", 2.5, "s", "breathing: the period (paper: 2.5 s)", io::Range::positive());
  io::declareDouble(p, "breathing exponent", 1.75, "", "breathing: the exponent (paper: 1.75)", io::Range::positive());
  io::declareDouble(p, "breathing start", 0.0, "s", "breathing: when the first breath begins (0 before)");
  io::declareString(p, "rectification", "half-wave",
                    "breathing: half-wave max(sin, 0) (one breath per period) or full-wave |sin|",
                    {"half-wave", "full-wave"});
  return p;
}

TimeFunction TimeFunction::fromParameters(const Teuchos::ParameterList &list, double endTime) {
  const auto type = list.get<std::string>("type");
  if (type == "constant") return constant();
  if (type == "breathing") {
    loads::BreathingProfile b;
    b.period = list.get<double>("breathing period");
    b.exponent = list.get<double>("breathing exponent");
    b.start = list.get<double>("breathing start");
    b.rectification = list.get<std::string>("rectification") == "full-wave"
                          ? loads::BreathingProfile::Rectification::FullWave
                          : loads::BreathingProfile::Rectification::HalfWave;
    return breathing(b);
  }
  if (type == "ramp") {
    const double d = list.get<double>("ramp duration");
    return ramp(d > 0.0 ? d : endTime);
  }
  const auto &t = list.get<Teuchos::Array<double>>("times");
  const auto &v = list.get<Teuchos::Array<double>>("values");
  std::vector<double> times(t.begin(), t.end()), values(v.begin(), v.end());
  return type == "steps" ? steps(std::move(times), std::move(values)) : table(std::move(times), std::move(values));
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
