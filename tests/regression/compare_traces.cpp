// compare_traces: a run's traces.csv (and summary.json) against a stored reference trace.
//
//   compare_traces REFERENCE.csv RUN_DIR [--tolerance T] [--max-dilatation D]
//
// Every (time, point) row of the reference must be in RUN_DIR/traces.csv, its time within
// T x (the reference's last time) (times of an arc-length run are results) and each displacement
// component within T x (the largest |u| component of the reference) (default 1e-6), and no row
// may be missing or extra. With --max-dilatation, every step of RUN_DIR/summary.json must have a
// max_dilatation_error <= D; the run must have converged. Prints the largest deviation and where;
// exit status 0 when it matches, 1 when not, 2 for unreadable input.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

namespace {
using Key = std::pair<double, std::string>;
using Trace = std::map<Key, std::array<double, 3>>;

Trace read(const std::string &file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file);
  std::string line;
  std::getline(in, line);
  // The reference's first five columns; later columns (dx, dy, dz) are not compared here. Column
  // names carry their unit ("ux [m]"); traces written before the units were added have none.
  std::string names;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line.compare(i, 2, " [") == 0) i = line.find(']', i);
    else names += line[i];
    if (i == std::string::npos) break;
  }
  if (names.rfind("time,point,ux,uy,uz", 0) != 0) throw std::runtime_error(file + ": not a traces.csv (header '" + line + "')");
  Trace t;
  for (int n = 2; std::getline(in, line); ++n) {
    std::stringstream s(line);
    std::string time, point, c[3];
    std::getline(s, time, ',');
    std::getline(s, point, ',');
    for (auto &v : c) std::getline(s, v, ',');
    if (c[2].empty()) throw std::runtime_error(file + ":" + std::to_string(n) + ": incomplete row");
    t[{std::stod(time), point}] = {std::stod(c[0]), std::stod(c[1]), std::stod(c[2])};
  }
  return t;
}
} // namespace

int main(int argc, char **argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: compare_traces REFERENCE.csv RUN_DIR [--tolerance T] [--max-dilatation D]\n");
    return 2;
  }
  double tolerance = 1e-6, maxDilatation = -1.0;
  for (int i = 3; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--tolerance")) tolerance = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--max-dilatation")) maxDilatation = std::atof(argv[i + 1]);
    else {
      std::fprintf(stderr, "compare_traces: unknown option %s\n", argv[i]);
      return 2;
    }
  }
  try {
    const Trace reference = read(argv[1]);
    const Trace run = read(std::string(argv[2]) + "/traces.csv");
    double scale = 0.0, lastTime = 0.0;
    for (const auto &[key, u] : reference) {
      for (double v : u) scale = std::max(scale, std::abs(v));
      lastTime = std::max(lastTime, std::abs(key.first));
    }
    // A row's time is a key when the steps are prescribed (written with 17 digits, so equal to
    // round-off) and a result when an arc-length run chooses it: either way it is held to the
    // displacements' relative tolerance, against the reference's largest time, and the nearest
    // row of the same point within it is the match.
    const double timeWindow = std::max(1e-12, tolerance * lastTime);
    bool ok = true;
    double worst = 0.0, worstTime = 0.0;
    Key worstAt{0.0, ""};
    for (const auto &[key, u] : reference) {
      auto match = run.end();
      for (auto it = run.lower_bound({key.first - timeWindow, ""});
           it != run.end() && it->first.first <= key.first + timeWindow; ++it)
        if (it->first.second == key.second &&
            (match == run.end() || std::abs(it->first.first - key.first) < std::abs(match->first.first - key.first)))
          match = it;
      if (match == run.end()) {
        std::printf("missing: t = %.17g point %s\n", key.first, key.second.c_str());
        ok = false;
        continue;
      }
      worstTime = std::max(worstTime, std::abs(match->first.first - key.first));
      for (int c = 0; c < 3; ++c) {
        const double d = std::abs(match->second[c] - u[c]);
        if (d > worst) {
          worst = d;
          worstAt = key;
        }
      }
    }
    if (run.size() != reference.size()) {
      std::printf("the run has %zu rows, the reference %zu\n", run.size(), reference.size());
      ok = false;
    }
    std::printf("largest deviation %.3e = %.3e of the largest displacement %.3e (t = %.6g, %s); tolerance %.1e\n",
                worst, scale > 0 ? worst / scale : 0.0, scale, worstAt.first, worstAt.second.c_str(), tolerance);
    if (worst > tolerance * scale) ok = false;
    if (worstTime > 1e-12)
      std::printf("largest time deviation %.3e s = %.3e of the last time %.6g\n", worstTime,
                  lastTime > 0 ? worstTime / lastTime : 0.0, lastTime);
    if (maxDilatation >= 0.0) {
      std::ifstream in(std::string(argv[2]) + "/summary.json");
      const auto summary = nlohmann::json::parse(in);
      if (!summary.value("converged", false)) {
        std::printf("the run did not converge\n");
        ok = false;
      }
      double largest = 0.0;
      for (const auto &step : summary.at("steps")) largest = std::max(largest, step.at("max_dilatation_error").get<double>());
      std::printf("largest dilatation error %.3e (bound %.1e)\n", largest, maxDilatation);
      if (largest > maxDilatation) ok = false;
    }
    std::printf("%s\n", ok ? "MATCH" : "MISMATCH");
    return ok ? 0 : 1;
  } catch (const std::exception &e) {
    std::fprintf(stderr, "compare_traces: %s\n", e.what());
    return 2;
  }
}
