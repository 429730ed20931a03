#include "contact/SurfaceText.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "contact/SurfaceError.hpp"

namespace glossa::contact::surface_text {

std::string readBytes(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SurfaceError(path + ": cannot open");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw SurfaceError(path + ": cannot read");
  return buffer.str();
}

Lines::Lines(const std::string &text) : text_(text) {}

bool Lines::next(std::string &line) {
  if (pos_ >= text_.size()) return false;
  std::size_t end = text_.find('\n', pos_);
  if (end == std::string::npos) end = text_.size();
  line = text_.substr(pos_, end - pos_);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  pos_ = end + 1;
  ++number_;
  return true;
}

std::vector<std::string> tokens(const std::string &line) {
  std::vector<std::string> out;
  std::istringstream s(line);
  for (std::string t; s >> t;) out.push_back(t);
  return out;
}

bool parseDouble(const std::string &token, double &value) {
  if (token.empty()) return false;
  errno = 0;
  char *end = nullptr;
  const double v = std::strtod(token.c_str(), &end);
  if (errno == ERANGE || end != token.c_str() + token.size() || !std::isfinite(v)) return false;
  value = v;
  return true;
}

void fail(const std::string &file, std::size_t line, const std::string &reason) {
  throw SurfaceError(file + ":" + std::to_string(line) + ": " + reason);
}

void checkScale(double scale) {
  if (!(std::isfinite(scale) && scale > 0)) {
    throw std::invalid_argument("a surface's length scale must be positive and finite, not " +
                                std::to_string(scale));
  }
}

}  // namespace glossa::contact::surface_text
