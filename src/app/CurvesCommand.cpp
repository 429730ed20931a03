#include "app/CurvesCommand.hpp"

#include <fstream>
#include <functional>
#include <iomanip>
#include <stdexcept>
#include <string>

#include "materials/ContractileCurveSets.hpp"
#include "materials/ParallelElement.hpp"
#include "materials/SeriesElement.hpp"

namespace glossa::app {
namespace {

namespace fs = std::filesystem;
using materials::ContractileCurves;

// Grid points (first + i step) for i = 0..n-1, computed as an integer over `scale` so that
// round values (lambda_c = 1, rate = 0) are exact: x_i = (first + i step) / scale.
std::vector<double> grid(long first, long step, long n, double scale) {
  std::vector<double> x;
  x.reserve(static_cast<std::size_t>(n));
  for (long i = 0; i < n; ++i) x.push_back(static_cast<double>(first + i * step) / scale);
  return x;
}

fs::path writeTable(const fs::path &file, const std::string &header, const std::vector<double> &x,
                    const std::vector<std::function<double(double)>> &columns) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error("cannot write " + file.string());
  out << std::setprecision(17) << header << '\n';
  for (double xi : x) {
    out << xi;
    for (const auto &f : columns) out << ',' << f(xi);
    out << '\n';
  }
  if (!out) throw std::runtime_error("error writing " + file.string());
  return file;
}

}  // namespace

std::vector<fs::path> writeCurveTables(const fs::path &directory) {
  fs::create_directories(directory);
  const ContractileCurves phys = materials::physiologicalCurves();
  const ContractileCurves paper = materials::paperTableIICurves();
  const auto parallel = materials::ParallelElement::tableI();
  const auto series = materials::SeriesElement::tableI(parallel.T0max());
  const double T0max = parallel.T0max();

  std::vector<fs::path> written;
  written.push_back(writeTable(directory / "force_length.csv",
                               "lambda_c [-],f_cL_physiological [-],f_cL_paper_table_II [-]",
                               grid(300, 5, 381, 1000.0),  // 0.3 .. 2.2
                               {[&](double l) { return phys.forceLength->evaluate(l).value; },
                                [&](double l) { return paper.forceLength->evaluate(l).value; }}));
  written.push_back(writeTable(directory / "force_velocity.csv",
                               "lambda_c_rate [1/s],f_cV_physiological [-],f_cV_paper_table_II [-]",
                               grid(-1200, 5, 481, 100.0),  // -12 .. 12 1/s
                               {[&](double v) { return phys.forceVelocity->evaluate(v).value; },
                                [&](double v) { return paper.forceVelocity->evaluate(v).value; }}));
  written.push_back(writeTable(directory / "passive_series.csv", "lambda [-],f_p [-],f_s [-]",
                               grid(800, 2, 401, 1000.0),  // 0.8 .. 1.6
                               {[&](double l) { return parallel.evaluate(l).T / T0max; },
                                // lambda_c = 1: lambda_s = lambda_f = lambda (eq. 13)
                                [&](double l) { return series.evaluate(l, 1.0).T / T0max; }}));
  return written;
}

}  // namespace glossa::app
