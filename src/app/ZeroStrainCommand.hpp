#pragma once
// glossa zero-strain (doc/tongue.md): the zero-strain configuration of a deck loaded by gravity,
// stored as reference nodal coordinates that later runs reuse (Mesh/reference coordinates file).
//  approximate (the paper): X0 = X_img + u, u the displacement under the deck's gravity reversed
//              and scaled by 'gravity factor' (1.2) on the imaged geometry X_img;
//  inverse:    the fixed point X_{k+1} = X_k + (X_img - x(X_k)), X_0 = X_img, x(X_k) = X_k + u
//              the configuration the deck's gravity produces from the reference X_k, until
//              max_n |x(X_k) - X_img| <= tolerance h (h the mean element edge of X_img).
// Every solve is the deck's own run (solvers::runSimulation) with its scene adjusted
// (RunOptions::adjustScene: the current iterate as reference positions, the gravity reversed for
// approximate): no solver set-up is duplicated here and no deck is rewritten.

#include <Teuchos_Comm.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/deck/Deck.hpp"
#include "solvers/parameters/RunConfiguration.hpp"

namespace glossa::app {

struct ZeroStrainResult {
  std::string method;
  bool converged = false;     // inverse: the tolerance was met; approximate: always true
  int iterations = 0;         // inverse: reference updates made; approximate: 1
  int solves = 0;             // forward solves (runs of the deck), the check included
  double meshSize = 0.0;      // h, mean element edge of the imaged geometry [m]
  double tolerance = 0.0;     // inverse: absolute bound on the max distance [m]
  double maxDistance = 0.0;   // max_n |x_n - X_img,n| of the stored configuration under gravity [m]
  double meanDistance = 0.0;  // mean over the nodes [m]
  double seconds = 0.0;
  nlohmann::json history;         // per forward solve: max, mean distance, seconds
  std::vector<double> reference;  // the stored coordinates, 3 per node
};

// Computes the zero-strain configuration of a validated deck (`config`: its solver sections,
// parsed once and handed to every forward run; the
// method is its Zero strain section, input/ZeroStrainParameters.hpp) and writes it to `output` (the
// coordinates file) and `output` with extension .json (the report); the forward runs' result
// files go to `output` without extension + "_runs/". Collective. Throws io::DeckError for a
// deck that does not fit (no gravity load, other loads, a reference coordinates file already
// set) and std::runtime_error when a forward solve does not converge.
ZeroStrainResult computeZeroStrain(const io::Deck &deck, const solvers::RunConfiguration &config,
                                   const Teuchos::RCP<const Teuchos::Comm<int>> &comm,
                                   const std::filesystem::path &output, bool quiet);

}  // namespace glossa::app
