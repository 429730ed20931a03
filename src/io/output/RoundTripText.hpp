#pragma once
// Numbers in our text outputs (traces.csv, XDMF time values) must read back bit-exactly, and must
// not depend on the process locale (a German locale would print "0,5" into a CSV): 17 significant
// digits through std::to_chars, which is locale-free and round-trips every finite double.

#include <charconv>
#include <string>

namespace glossa::io {

inline std::string roundTripText(double value) {
  // 32 characters hold any double at 17 digits ("-1.2345678901234567e-308" is 24).
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 17);
  return std::string(buffer, result.ptr);
}

} // namespace glossa::io
