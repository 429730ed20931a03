#pragma once
// `glossa point DECK.xml`: one material point of the deck's Material driven along a prescribed
// deformation path with the deck's muscle-group inputs (doc/materials.md, "Material-point driver"), for calibration and
// for checking a material before it goes into a scene. Paths (the deck's "Point" section):
//   uniaxial      F = lambda e(x)e + lambda^{-1/2} (1 - e(x)e): incompressible stretch along e
//   simple shear  F = 1 + gamma e(x)m, m the shear plane's normal (orthogonal to e)
//   table         F(t) given row by row (9 values, row-major), linear in time between rows
// with lambda = 1 + amplitude s(t), gamma = amplitude s(t), s the path's time function. Time
// steps are the deck's Time section; activation follows eq. 24 per group, lambda_c is solved and
// committed per step, exactly as at a quadrature point of a scene.
//
// Writes CSV (17 significant digits): time, the path parameter, the energy and the isochoric
// Cauchy stress (J = 1 paths: the whole stress but the pressure), the axial stress
// e.sigma.e - (t1.sigma.t1 + t2.sigma.t2)/2 (the uniaxial stress when the lateral faces are free
// and the law is transversely isotropic about e), then per fibre family lambda_f, lambda_c, T
// and per muscle group alpha.

#include <filesystem>

#include "io/deck/Deck.hpp"
#include "solvers/parameters/TimeParameters.hpp"

namespace glossa::app {

// `deck` validated against the schema, `time` its Time section. Throws io::DeckError for a deck
// the driver cannot use, std::runtime_error if the point law fails along the path (naming the
// time and why). Returns the number of rows written.
int runPointDriver(const io::Deck &deck, const solvers::TimeParameters &time, const std::filesystem::path &csv);

} // namespace glossa::app
