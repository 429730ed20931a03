#pragma once
// What the surface readers (OBJ, STL) share: the file's bytes, its lines with their numbers
// (LF or CRLF, a last line without a newline), whitespace tokens, strict number parsing, and
// "file:line: reason" errors thrown as SurfaceError.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace glossa::contact::surface_text {

// The whole file; throws SurfaceError "path: cannot open" when it cannot be read.
std::string readBytes(const std::string &path);

// Lines of a text, numbered from 1, without their terminators.
class Lines {
 public:
  explicit Lines(const std::string &text);
  bool next(std::string &line);
  std::size_t number() const { return number_; }

 private:
  const std::string &text_;
  std::size_t pos_ = 0, number_ = 0;
};

std::vector<std::string> tokens(const std::string &line);
// Whole-token parse: "1.5x", "", "nan", "inf" and Fortran's "1.5D0" fail. (Integers are
// parsed as the mesh readers parse them, mesh::importing::parseInt.)
bool parseDouble(const std::string &token, double &value);

[[noreturn]] void fail(const std::string &file, std::size_t line, const std::string &reason);
// The factor from the file's length unit to metres: positive and finite, else invalid_argument.
void checkScale(double scale);

}  // namespace glossa::contact::surface_text
