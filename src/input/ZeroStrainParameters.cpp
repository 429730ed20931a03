#include "input/ZeroStrainParameters.hpp"

#include <string>

#include "io/deck/DeckError.hpp"
#include "io/deck/ParameterSpec.hpp"

namespace glossa::input {

Teuchos::ParameterList zeroStrainParameters() {
  Teuchos::ParameterList p;
  io::declareString(
      p, "method", "inverse",
      "glossa zero-strain: approximate (the paper, §8.1: the imaged geometry deformed by the "
      "deck's gravity reversed and scaled by 'gravity factor') or inverse (fixed-point update of "
      "the reference coordinates until the deck's gravity maps them onto the imaged geometry)",
      {"approximate", "inverse"});
  io::declareDouble(p, "gravity factor", 1.2, "",
                    "approximate: the reversed gravity is this multiple of the deck's (the paper: 1.2)",
                    io::Range::positive());
  io::declareDouble(p, "tolerance", 1e-3, "",
                    "inverse: stop when the largest nodal distance between the configuration under gravity "
                    "and the imaged geometry is at most this multiple of the mean element edge",
                    io::Range::positive());
  io::declareInt(p, "maximum iterations", 10, "inverse: reference updates before giving up",
                 io::Range::closed(1, 1000));
  return p;
}

ZeroStrainParameters parseZeroStrainParameters(const io::Deck &deck) {
  const Teuchos::ParameterList &z = deck.root().sublist("Zero strain");
  ZeroStrainParameters p;
  p.method = z.get<std::string>("method") == "approximate" ? ZeroStrainMethod::approximate : ZeroStrainMethod::inverse;
  p.gravityFactor = z.get<double>("gravity factor");
  p.tolerance = z.get<double>("tolerance");
  p.maximumIterations = z.get<int>("maximum iterations");
  return p;
}

void requireImagedGeometryUnderGravity(const io::Deck &deck, const model::Scene &imaged) {
  if (!imaged.mesh.imagedNodes.empty())
    throw io::DeckError(
        deck.where({"Mesh", "reference coordinates file"}) +
        ": glossa zero-strain starts from the mesh as read (the imaged geometry); leave it empty");
  auto refuse = [&](const std::string &name, const std::string &kind) {
    throw io::DeckError(deck.where({"Loads", name, "type"}) +
                        ": glossa zero-strain needs a deck loaded by gravity alone (the configuration "
                        "gravity maps onto the imaged geometry); '" + name + "' is a " + kind + " load");
  };
  for (const auto &l : imaged.tractions) refuse(l.name, "dead traction");
  for (const auto &l : imaged.pressures) refuse(l.name, "follower pressure");
  for (const auto &l : imaged.bodyForces)
    if (!l.gravity) refuse(l.name, "body force");
  if (imaged.bodyForces.empty())
    throw io::DeckError(deck.where({"Loads"}) + ": glossa zero-strain needs at least one gravity load");
}

} // namespace glossa::input
