#include "app/ZeroStrainCommand.hpp"

#include <chrono>
#include <cstdio>
#include <fstream>

#include "input/SceneFactory.hpp"
#include "input/ZeroStrainParameters.hpp"
#include "mesh/ReferenceCoordinates.hpp"
#include "solvers/run/RunSimulation.hpp"

namespace glossa::app {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Mean length of the 12 edges of every hexahedron (VTK numbering: 0-3 bottom, 4-7 top).
double meanEdgeLength(const mesh::HexMesh &m) {
  static const int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                   {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  double sum = 0.0;
  for (const auto &e : m.elements)
    for (const auto &edge : edges) sum += (m.nodes[e[edge[1]]] - m.nodes[e[edge[0]]]).norm();
  return m.elements.empty() ? 0.0 : sum / (12.0 * static_cast<double>(m.elements.size()));
}

std::vector<Eigen::Vector3d> displaced(const std::vector<Eigen::Vector3d> &X, const std::vector<double> &u) {
  std::vector<Eigen::Vector3d> x(X);
  for (std::size_t n = 0; n < x.size(); ++n) x[n] += Eigen::Vector3d(u[3 * n], u[3 * n + 1], u[3 * n + 2]);
  return x;
}

struct Distance {
  double max = 0.0, mean = 0.0;
};
Distance distance(const std::vector<Eigen::Vector3d> &x, const std::vector<Eigen::Vector3d> &target) {
  Distance d;
  for (std::size_t n = 0; n < x.size(); ++n) {
    const double r = (x[n] - target[n]).norm();
    d.max = std::max(d.max, r);
    d.mean += r;
  }
  if (!x.empty()) d.mean /= static_cast<double>(x.size());
  return d;
}

// The zero-strain reference coordinates to `output` and its report beside it (.json). Rank 0.
void writeZeroStrain(const io::Deck &deck, const input::ZeroStrainParameters &z, const ZeroStrainResult &result,
                     const std::vector<Eigen::Vector3d> &X, const std::filesystem::path &output, bool quiet) {
  char line[256];
  std::snprintf(line, sizeof line, "under the deck's gravity: max |x - X_img| = %.6e m, mean %.6e m",
                result.maxDistance, result.meanDistance);
  std::vector<std::string> header{"zero-strain configuration (paper §8.1, doc/tongue.md s8_1) of " + deck.file(),
                                  "method " + result.method + ", " + std::to_string(result.iterations) +
                                      " iteration(s), " + std::to_string(result.solves) +
                                      " forward solves" + (result.converged ? "" : ", TOLERANCE NOT MET"),
                                  line};
  mesh::writeReferenceCoordinates(output.string(), X, header);
  nlohmann::json report;
  report["deck"] = deck.file();
  report["method"] = result.method;
  report["converged"] = result.converged;
  report["iterations"] = result.iterations;
  report["solves"] = result.solves;
  report["mesh_size"] = result.meshSize;
  if (z.method == input::ZeroStrainMethod::inverse)
    report["tolerance"] = result.tolerance;
  else
    report["gravity_factor"] = z.gravityFactor;
  report["max_distance"] = result.maxDistance;
  report["mean_distance"] = result.meanDistance;
  report["seconds"] = result.seconds;
  report["runs"] = result.history;
  std::filesystem::path json = output;
  json.replace_extension(".json");
  std::ofstream(json) << report.dump(2) << '\n';
  if (!quiet)
    std::printf("zero-strain: %s, %d iteration(s), %d solves, %.1f s; wrote %s and %s\n",
                result.method.c_str(), result.iterations, result.solves, result.seconds, output.c_str(),
                json.c_str());
}
}  // namespace

ZeroStrainResult computeZeroStrain(const io::Deck &deck, const solvers::RunConfiguration &config,
                                   const Teuchos::RCP<const Teuchos::Comm<int>> &comm,
                                   const std::filesystem::path &output, bool quiet) {
  const auto start = Clock::now();
  const bool root = comm->getRank() == 0;
  const input::ZeroStrainParameters z = input::parseZeroStrainParameters(deck);

  ZeroStrainResult result;
  result.method = z.method == input::ZeroStrainMethod::approximate ? "approximate" : "inverse";
  const model::Scene imaged = input::buildScene(deck, config.time.rampEndTime);
  input::requireImagedGeometryUnderGravity(deck, imaged);
  const std::vector<Eigen::Vector3d> &Ximg = imaged.mesh.nodes;
  result.meshSize = meanEdgeLength(imaged.mesh);
  result.tolerance = z.tolerance * result.meshSize;
  result.history = nlohmann::json::array();

  std::filesystem::path runs = output;
  runs.replace_extension("");
  runs += "_runs";
  if (root) std::filesystem::create_directories(runs);
  comm->barrier();

  // One run of the deck from the reference X, its gravity times `gravityFactor`: x = X + u at the
  // end time. The scene is the deck's with these two changes (RunOptions::adjustScene).
  auto forward = [&](const std::vector<Eigen::Vector3d> &X, double gravityFactor, const std::string &label) {
    const auto t0 = Clock::now();
    std::vector<double> u;
    solvers::RunOptions options;
    options.outputDirectory = runs / label;
    options.quiet = true;
    options.finalDisplacement = &u;
    options.adjustScene = [&](model::Scene &scene) {
      model::useReferenceNodes(scene, X);
      for (auto &gravity : scene.bodyForces) gravity.acceleration *= gravityFactor;
    };
    const auto summary = solvers::runSimulation(deck, config, comm, options);
    if (!summary.value("converged", false))
      throw std::runtime_error("glossa zero-strain: the forward run " + label + " did not converge (" +
                               summary.value("failure", std::string("no reason given")) + "); results in " +
                               (runs / label).string());
    ++result.solves;
    return std::make_pair(displaced(X, u), since(t0));
  };
  auto record = [&](const std::string &label, const Distance &d, double seconds) {
    result.history.push_back(
        {{"run", label}, {"max_distance", d.max}, {"mean_distance", d.mean}, {"seconds", seconds}});
    if (root && !quiet)
      std::printf("zero-strain: %-12s max |x - X_img| = %.4e m  mean %.4e m  (%.1f s)\n", label.c_str(),
                  d.max, d.mean, seconds);
  };

  std::vector<Eigen::Vector3d> X = Ximg;
  if (z.method == input::ZeroStrainMethod::approximate) {
    // The deck's gravity reversed and scaled, on the imaged geometry.
    const auto [x, seconds] = forward(Ximg, -z.gravityFactor, "unload");
    record("unload", distance(x, Ximg), seconds);
    X = x;
    const auto [xg, checkSeconds] = forward(X, 1.0, "check");
    const Distance d = distance(xg, Ximg);
    record("check", d, checkSeconds);
    result.iterations = 1;
    result.converged = true;
    result.maxDistance = d.max;
    result.meanDistance = d.mean;
  } else {
    const int maxIterations = z.maximumIterations;
    for (int k = 0;; ++k) {
      const auto [x, seconds] = forward(X, 1.0, "iteration_" + std::to_string(k));
      const Distance d = distance(x, Ximg);
      record("iteration_" + std::to_string(k), d, seconds);
      result.maxDistance = d.max;
      result.meanDistance = d.mean;
      result.iterations = k;
      if (d.max <= result.tolerance) {
        result.converged = true;
        break;
      }
      if (k == maxIterations) break;
      for (std::size_t n = 0; n < X.size(); ++n) X[n] += Ximg[n] - x[n];  // X_{k+1} = X_k + (X_img - x(X_k))
    }
  }
  result.seconds = since(start);
  for (const auto &x : X)
    for (int c = 0; c < 3; ++c) result.reference.push_back(x(c));

  if (root) writeZeroStrain(deck, z, result, X, output, quiet);
  comm->barrier();
  return result;
}

}  // namespace glossa::app
