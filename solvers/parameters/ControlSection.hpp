#pragma once
// The deck's "Control" section (paper §6.1, doc/control.md): which points are held (eq. 25), which
// muscle groups the controller drives, and the elitist GA's parameters (control/). Teuchos only.

#include <string>
#include <vector>

#include <Eigen/Core>
#include <Teuchos_ParameterList.hpp>

#include "control/ControllerParameters.hpp"
#include "io/deck/Deck.hpp"
#include "model/Scene.hpp"

namespace glossa::solvers {

Teuchos::ParameterList controlParameters();

struct ControlSetup {
  bool enabled = false;
  control::ControllerParameters parameters;
  std::vector<std::string> pointNames;
  std::vector<mesh::NodeId> pointNodes;
  // xbar_p of eq. 25, one column per point: the points' imaged positions (the mesh as read),
  // which are the reference positions unless a zero-strain configuration replaced them (§8.1).
  Eigen::Matrix3Xd goals;
  Eigen::VectorXd weights;
  std::vector<int> groups; // the controlled muscle groups (scene indices), ascending
};

// `deck` validated; errors are DeckErrors naming the parameter (an unknown point or group, a
// weight count that does not match, GA parameters out of range).
ControlSetup buildControl(const io::Deck &deck, const model::Scene &scene);

// Whether the section asks for a controller (type other than none), before the scene is there.
bool controlRequested(const Teuchos::ParameterList &controlSection);

} // namespace glossa::solvers
