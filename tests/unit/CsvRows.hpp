#pragma once
// A CSV file written by glossa (header "name [unit],..."), read back as rows keyed by column name
// without its unit, for tests that check its values; a column that is not a number (the key of a
// keyed CSV, e.g. "airway") reads as NaN.

#include <cstdlib>
#include <filesystem>
#include <limits>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace glossa::test {

inline std::vector<std::map<std::string, double>> readCsvRows(const std::filesystem::path &csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream header(line);
  for (std::string c; std::getline(header, c, ',');) names.push_back(c.substr(0, c.find(" [")));
  std::vector<std::map<std::string, double>> rows;
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::map<std::string, double> row;
    std::string c;
    for (const auto &n : names) {
      std::getline(s, c, ',');
      char *end = nullptr;
      const double value = std::strtod(c.c_str(), &end);
      row[n] = end == c.c_str() ? std::numeric_limits<double>::quiet_NaN() : value;
    }
    rows.push_back(row);
  }
  return rows;
}

} // namespace glossa::test
