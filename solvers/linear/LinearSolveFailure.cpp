#include "solvers/linear/LinearSolveFailure.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <vector>

namespace glossa::solvers {

namespace {
bool contains(const std::string &text, const char *needle) {
  std::string lower(text), key(needle);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  std::transform(key.begin(), key.end(), key.begin(), [](unsigned char c) { return std::tolower(c); });
  return lower.find(key) != std::string::npos;
}

// A line of Teuchos' exception frame: "/path/file.hpp:698:", "Throw number = 1",
// "Throw test that evaluated to true: ...".
bool isFrameLine(const std::string &line) {
  if (line.rfind("Throw number", 0) == 0 || line.rfind("Throw test that evaluated to true", 0) == 0) return true;
  const auto colon = line.find_last_of(':');
  if (colon == std::string::npos || colon + 1 != line.size()) return false;
  const std::string head = line.substr(0, colon);
  const auto lineColon = head.find_last_of(':');
  if (lineColon == std::string::npos) return false;
  const std::string file = head.substr(0, lineColon), number = head.substr(lineColon + 1);
  const bool digits = !number.empty() && std::all_of(number.begin(), number.end(), [](unsigned char c) { return std::isdigit(c); });
  const bool source = file.size() > 4 && (file.find(".hpp") != std::string::npos || file.find(".cpp") != std::string::npos ||
                                          file.find(".h") != std::string::npos);
  return digits && source;
}
} // namespace

std::string linearSolveFailure(const std::string &exceptionText) {
  std::istringstream in(exceptionText);
  std::string message;
  for (std::string line; std::getline(in, line);) {
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    line = line.substr(first);
    if (isFrameLine(line)) continue;
    message += (message.empty() ? "" : " ") + line;
  }
  if (message.empty()) message = "no reason given";
  std::string words;
  if (contains(message, "p^H*A*p") || contains(message, "negative curvature") || contains(message, "not positive definite"))
    words = "CG met negative curvature p^T A p <= 0: the tangent is not positive definite here";
  else if (contains(message, "r^H*M*r") || contains(message, "preconditioner is not positive"))
    words = "CG met r^T M r < 0: the preconditioner is not positive definite here";
  else if (contains(message, "loss of accuracy"))
    words = "loss of accuracy in the Krylov iteration";
  else if (contains(message, "OrthoFailure") || contains(message, "orthogonalization") || contains(message, "orthogonalisation"))
    words = "the Krylov basis could not be orthogonalised (loss of accuracy)";
  else if (contains(message, "LAPACK"))
    words = "a LAPACK routine failed inside the Krylov solver";
  else if (contains(message, "breakdown"))
    words = "Krylov breakdown";
  return words.empty() ? message : words + " (" + message + ")";
}

} // namespace glossa::solvers
