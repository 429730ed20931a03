#include "io/deck/StrictNumber.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace glossa::io {

namespace {
std::string trimmed(const std::string &text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r\n");
  return text.substr(first, last - first + 1);
}

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// Length of the run of digits starting at `i`.
std::size_t digitsAt(const std::string &s, std::size_t i) {
  std::size_t n = 0;
  while (i + n < s.size() && isDigit(s[i + n])) ++n;
  return n;
}

bool isDecimal(const std::string &s) {
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  const std::size_t whole = digitsAt(s, i);
  i += whole;
  std::size_t fraction = 0;
  if (i < s.size() && s[i] == '.') {
    ++i;
    fraction = digitsAt(s, i);
    i += fraction;
  }
  if (whole == 0 && fraction == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    const std::size_t exponent = digitsAt(s, i);
    if (exponent == 0) return false;
    i += exponent;
  }
  return i == s.size();
}

bool isInteger(const std::string &s) {
  std::size_t i = (!s.empty() && (s[0] == '+' || s[0] == '-')) ? 1 : 0;
  const std::size_t n = digitsAt(s, i);
  return n > 0 && i + n == s.size();
}

std::string quoted(const std::string &text) { return "'" + text + "'"; }

// The entries of an array text, each trimmed; refuses empty entries.
std::vector<std::string> entriesOf(const std::string &text, bool bracesRequired) {
  std::string inner = trimmed(text);
  const bool open = !inner.empty() && inner.front() == '{';
  const bool close = !inner.empty() && inner.back() == '}';
  if (open != close || (bracesRequired && !open))
    throw std::invalid_argument(quoted(text) + " is not an array: write it as {a, b, c}");
  if (open) inner = trimmed(inner.substr(1, inner.size() - 2));
  std::vector<std::string> entries;
  if (inner.empty()) return entries;
  std::size_t start = 0;
  while (true) {
    const auto comma = inner.find(',', start);
    const std::string entry = trimmed(inner.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (entry.empty())
      throw std::invalid_argument(quoted(text) + " has an empty entry " + std::to_string(entries.size() + 1) +
                                  " (two commas in a row, or a comma at an end)");
    entries.push_back(entry);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return entries;
}

template <class T, class Parse>
std::vector<T> parseEach(const std::string &text, bool bracesRequired, Parse parse) {
  std::vector<T> values;
  for (const auto &entry : entriesOf(text, bracesRequired)) {
    try {
      values.push_back(parse(entry));
    } catch (const std::invalid_argument &e) {
      throw std::invalid_argument("entry " + std::to_string(values.size() + 1) + " of " + quoted(text) + ": " + e.what());
    }
  }
  return values;
}
} // namespace

double parseStrictDouble(const std::string &text) {
  const std::string s = trimmed(text);
  if (s.empty()) throw std::invalid_argument("the value is empty; a number is needed");
  if (!isDecimal(s))
    throw std::invalid_argument(quoted(text) + " is not a number (write a decimal such as 0.4999 or 1e-3; "
                                "no decimal comma, units, inf, nan or hexadecimal)");
  errno = 0;
  const double value = std::strtod(s.c_str(), nullptr);
  if (errno == ERANGE && std::isinf(value))
    throw std::invalid_argument(quoted(text) + " is beyond the range of a double (about 1.8e308)");
  return value; // an underflow to 0 or a denormal is the nearest double, as the text means
}

namespace {
// A decimal text as sign, significant digits and the exponent of the first of them (so that
// equal numbers give equal triples); zero is {false, "", 0}.
struct DecimalForm {
  bool negative = false;
  std::string digits;
  long long exponent = 0;
  bool operator==(const DecimalForm &o) const {
    return negative == o.negative && digits == o.digits && exponent == o.exponent;
  }
};

DecimalForm decimalForm(const std::string &text) {
  const std::string s = trimmed(text);
  DecimalForm f;
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) f.negative = s[i++] == '-';
  long long pointAt = -1;
  for (; i < s.size() && s[i] != 'e' && s[i] != 'E'; ++i) {
    if (s[i] == '.') pointAt = static_cast<long long>(f.digits.size());
    else f.digits += s[i];
  }
  if (pointAt < 0) pointAt = static_cast<long long>(f.digits.size());
  long long exponent = 0;
  if (i < s.size()) {
    ++i;
    bool negativeExponent = false;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) negativeExponent = s[i++] == '-';
    // Beyond 10^9 the text is far outside a double's range whatever its digits.
    for (; i < s.size(); ++i) exponent = std::min(exponent * 10 + (s[i] - '0'), 1000000000LL);
    if (negativeExponent) exponent = -exponent;
  }
  const auto first = f.digits.find_first_not_of('0');
  if (first == std::string::npos) return {};
  f.digits = f.digits.substr(first, f.digits.find_last_not_of('0') - first + 1);
  f.exponent = pointAt - static_cast<long long>(first) + exponent;
  return f;
}
} // namespace

bool sameDecimalValue(const std::string &a, const std::string &b) { return decimalForm(a) == decimalForm(b); }

int parseStrictInt(const std::string &text) {
  const std::string s = trimmed(text);
  if (s.empty()) throw std::invalid_argument("the value is empty; an integer is needed");
  if (!isInteger(s)) throw std::invalid_argument(quoted(text) + " is not an integer (decimal digits, no point or exponent)");
  errno = 0;
  const long long value = std::strtoll(s.c_str(), nullptr, 10);
  if (errno == ERANGE || value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max())
    throw std::invalid_argument(quoted(text) + " is beyond the range of an integer (" +
                                std::to_string(std::numeric_limits<int>::max()) + ")");
  return static_cast<int>(value);
}

bool parseStrictBool(const std::string &text) {
  const std::string s = trimmed(text);
  if (s == "true" || s == "1") return true;
  if (s == "false" || s == "0") return false;
  throw std::invalid_argument(quoted(text) + " is not true or false");
}

std::vector<double> parseStrictDoubleArray(const std::string &text, bool bracesRequired) {
  return parseEach<double>(text, bracesRequired, parseStrictDouble);
}

std::vector<int> parseStrictIntArray(const std::string &text, bool bracesRequired) {
  return parseEach<int>(text, bracesRequired, parseStrictInt);
}

} // namespace glossa::io
