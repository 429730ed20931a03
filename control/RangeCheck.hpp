#pragma once
// Validation of plain parameter structs: an out-of-range value is an error that names the field
// and its allowed range (doc/developing.md: decks validate, never guess). Internal to control/.

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace glossa::control::detail {

inline std::string formatBound(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  std::ostringstream s;
  s << v;
  return s.str();
}

// Throws std::invalid_argument unless lo <= value <= hi (lo < value when loOpen, value < hi
// when hiOpen); NaN is always out of range.
inline void requireInRange(const std::string &field, double value, double lo, double hi, bool loOpen = false,
                           bool hiOpen = false) {
  const bool aboveLo = loOpen ? value > lo : value >= lo;
  const bool belowHi = hiOpen ? value < hi : value <= hi;
  if (aboveLo && belowHi) return;
  std::ostringstream s;
  s << field << " = " << value << " is out of range: allowed " << (loOpen ? "(" : "[") << formatBound(lo)
    << ", " << formatBound(hi) << ((hiOpen || std::isinf(hi)) ? ")" : "]");
  throw std::invalid_argument(s.str());
}

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace glossa::control::detail
