#pragma once
// A deck's list of names, "C01 mid, C02 mid, GGa": comma separated, blanks around each name
// dropped, empty entries skipped.

#include <sstream>
#include <string>
#include <vector>

namespace glossa::io {

inline std::vector<std::string> splitNameList(const std::string &s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) {
    const auto b = item.find_first_not_of(' '), e = item.find_last_not_of(' ');
    if (b != std::string::npos) out.push_back(item.substr(b, e - b + 1));
  }
  return out;
}

} // namespace glossa::io
