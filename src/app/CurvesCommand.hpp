#pragma once
// `glossa curves`: tabulates the Hill muscle curves to CSV for calibration
// (doc/materials.md, "Plots of the curves"). Both contractile curve sets side by side:
//   force_length.csv    lambda_c, f_cL (eq. 19) over [0.3, 2.2], step 0.005 (contains 1 exactly)
//   force_velocity.csv  lambda_c_rate [1/s], f_cV (eq. 20) over [-12, 12], step 0.05
//   passive_series.csv  lambda, f_p = T_p/T0max (eq. 17), f_s = T_s/T0max (eq. 18) at lambda_c = 1,
//                       Table I values, over [0.8, 1.6], step 0.002
// Numbers with 17 significant digits.

#include <filesystem>
#include <vector>

namespace glossa::app {

// Creates `directory` if needed and writes the three tables; returns the paths written.
// Throws std::runtime_error if a file cannot be written.
std::vector<std::filesystem::path> writeCurveTables(const std::filesystem::path &directory);

}  // namespace glossa::app
