#include "input/TimeFunctionParameters.hpp"

#include <stdexcept>

#include "input/UnreadParameters.hpp"
#include "io/deck/DeckError.hpp"
#include "io/deck/ParameterSpec.hpp"

namespace glossa::input {

Teuchos::ParameterList timeFunctionParameters(const std::string &defaultType) {
  Teuchos::ParameterList p("time function");
  io::declareString(p, "type", defaultType,
                    "constant: 1 at all times; ramp: t/duration up to 1; table: piecewise linear "
                    "in 'times'/'values', constant beyond the ends; steps: values[i] from times[i] "
                    "to the next time (values[0] before the first); breathing: eq. 27, "
                    "sin(2 pi (t - start) / period)^exponent, rectified (doc/loads.md)",
                    {"constant", "ramp", "table", "steps", "breathing"});
  io::declareDouble(p, "ramp duration", 0.0, "s",
                    "time over which a ramp rises from 0 to 1; 0 means the deck's own end time (Time/end time "
                    "as the file gives it: --set \"Time/end time=...\" shortens or lengthens the run, not the ramp)",
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

model::TimeFunction parseTimeFunction(const Teuchos::ParameterList &list, double endTime) {
  using model::TimeFunction;
  const auto type = list.get<std::string>("type");
  if (type == "constant") return TimeFunction::constant();
  if (type == "breathing") {
    loads::BreathingProfile b;
    b.period = list.get<double>("breathing period");
    b.exponent = list.get<double>("breathing exponent");
    b.start = list.get<double>("breathing start");
    b.rectification = list.get<std::string>("rectification") == "full-wave"
                          ? loads::BreathingProfile::Rectification::FullWave
                          : loads::BreathingProfile::Rectification::HalfWave;
    return TimeFunction::breathing(b);
  }
  if (type == "ramp") {
    const double d = list.get<double>("ramp duration");
    return TimeFunction::ramp(d > 0.0 ? d : endTime);
  }
  const auto &t = list.get<Teuchos::Array<double>>("times");
  const auto &v = list.get<Teuchos::Array<double>>("values");
  std::vector<double> times(t.begin(), t.end()), values(v.begin(), v.end());
  return type == "steps" ? TimeFunction::steps(std::move(times), std::move(values)) : TimeFunction::table(std::move(times), std::move(values));
}

model::TimeFunction timeFunctionAt(const io::Deck &deck, const std::vector<std::string> &path, double endTime) {
  const Teuchos::ParameterList *list = &deck.root();
  for (const auto &p : path) list = &list->sublist(p);
  refuseUnreadTimeFunctionParameters(deck, path);
  try {
    return parseTimeFunction(*list, endTime);
  } catch (const std::invalid_argument &e) {
    throw io::DeckError(deck.where(path) + ": " + e.what());
  }
}

void refuseUnreadTimeFunctionParameters(const io::Deck &deck, const std::vector<std::string> &path) {
  // What parseTimeFunction reads for each type.
  static const std::vector<ReadUnder> readers{{"ramp duration", {"ramp"}},
                                              {"times", {"table", "steps"}},
                                              {"values", {"table", "steps"}},
                                              {"breathing period", {"breathing"}},
                                              {"breathing exponent", {"breathing"}},
                                              {"breathing start", {"breathing"}},
                                              {"rectification", {"breathing"}}};
  refuseUnreadParameters(deck, path, "type", readers);
}

} // namespace glossa::input
